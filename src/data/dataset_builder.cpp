#include "data/dataset_builder.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/hash.hpp"
#include "core/npy.hpp"
#include "core/number_text.hpp"
#include "core/output_path.hpp"
#include "core/parse.hpp"
#include "core/progress.hpp"
#include "data/captions.hpp"
#include "data/derived_clips.hpp"
#include "data/hml3d_dataset.hpp"
#include "data/mean_std.hpp"
#include "data/measured_captions.hpp"
#include "data/splits.hpp"
#include "motion/humanml3d.hpp"
#include "motion/mocap_import.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

namespace fs = std::filesystem;

namespace {

constexpr double kFps = 20.0;

struct ClipSource {
    std::string file, subject, source_dataset, licence, tags;
    std::vector<std::pair<std::pair<int, int>, CaptionLine>> captions;  // [start, end) frames at 20 fps
    nlohmann::json provenance;  // derived clips: source file, method, parameters, seed; null when captured
};

std::string field(const CsvTable& t, size_t row, const char* name) {
    return t.has_column(name) ? t.rows[row][t.column(name)] : std::string();
}

// Bandai Namco does not name its performers; its clips are grouped by acted style (the third part of the name).
std::string split_key(const ClipSource& c) {
    std::string key = c.source_dataset + "/" + (c.subject.empty() ? c.file : c.subject);
    if (c.source_dataset == "BandaiNamco") {
        const std::string stem = fs::path(c.file).stem().string();
        std::vector<std::string> parts;
        size_t a = 0, b;
        while ((b = stem.find('_', a)) != std::string::npos) {
            parts.push_back(stem.substr(a, b - a));
            a = b + 1;
        }
        if (parts.size() >= 3) key += "/" + parts[2];
    }
    return key;
}

std::map<std::string, ClipSource> read_sources(const BuildOptions& o) {
    const std::string captions_path = o.captions_csv.empty() ? o.mocap_dir + "/captions.csv" : o.captions_csv;
    const CsvTable captions = read_csv(captions_path);
    for (const char* col : {"file", "start_frame", "end_frame", "caption"}) captions.column(col);
    std::map<std::string, ClipSource> clips;
    const std::string manifest_path = o.mocap_dir + "/manifest.csv";
    if (fs::exists(manifest_path)) {
        const CsvTable m = read_csv(manifest_path);
        for (size_t r = 0; r < m.rows.size(); ++r) {
            ClipSource& c = clips[field(m, r, "file")];
            c.file = field(m, r, "file");
            c.subject = field(m, r, "subject");
            c.source_dataset = field(m, r, "source_dataset");
            c.licence = field(m, r, "licence");
            c.tags = field(m, r, "activity_tags");
        }
    }
    for (size_t r = 0; r < captions.rows.size(); ++r) {
        ClipSource& c = clips[field(captions, r, "file")];
        c.file = field(captions, r, "file");
        if (c.subject.empty()) c.subject = field(captions, r, "subject");
        if (c.licence.empty()) c.licence = field(captions, r, "licence");
        if (c.source_dataset.empty())
            c.source_dataset = field(captions, r, "source").empty() ? "user" : field(captions, r, "source");
        const std::string caption_licence = field(captions, r, "licence");
        if (!o.licences.empty() && caption_licence.rfind("KIT-ML", 0) == 0 && !o.licences.count("KIT-ML")) continue;
        CaptionLine line;
        line.caption = field(captions, r, "caption");
        line.tokens = field(captions, r, "tokens");
        const int start = static_cast<int>(captions.number(r, captions.column("start_frame")));
        const int end = static_cast<int>(captions.number(r, captions.column("end_frame")));
        c.captions.push_back({{start, end}, line});
    }
    return clips;
}

struct Written {
    std::string id;
    std::string split_key;
    FeatureMatrix features;
};

// Cuts [0, frames) into equal consecutive chunks of at most max_frames.
std::vector<std::pair<int, int>> chunks(int frames, int max_frames) {
    const int n = (frames + max_frames - 1) / max_frames;
    std::vector<std::pair<int, int>> out;
    for (int k = 0; k < n; ++k) out.push_back({k * frames / n, (k + 1) * frames / n});
    return out;
}

// At most `keep` of the chunks, spread evenly over the recording so that what is kept samples all of it.
std::vector<std::pair<int, int>> spread(const std::vector<std::pair<int, int>>& all, size_t keep) {
    if (keep == 0 || all.size() <= keep) return all;
    std::vector<std::pair<int, int>> out;
    for (size_t k = 0; k < keep; ++k) out.push_back(all[(2 * k + 1) * all.size() / (2 * keep)]);
    return out;
}

std::string decimal(double x) { return general_text(x, 9); }

// The recording at its capture rate (capture_fps_for), or nothing when that is 20 fps or less: the clip itself
// then is the capture.
std::optional<JointSequence> import_at_capture_rate(const std::string& path) {
    ImportOptions at_capture;
    at_capture.fps = 0;
    JointSequence s = import_motion(path, at_capture);
    if (s.fps <= kFps + 1e-9) return std::nullopt;
    return s;
}

JointSequence mirrored(const JointSequence& s) {
    JointSequence out = s;
    for (int f = 0; f < s.num_frames; ++f)
        for (int j = 0; j < s.num_joints; ++j) {
            Eigen::Vector3d p = s.at(f, smpl22::kMirror[static_cast<size_t>(j)]);
            p.x() = -p.x();
            out.at(f, j) = p;
        }
    return out;
}

std::vector<CaptionLine> captions_for_chunk(const ClipSource& c, int begin, int end, int frames) {
    std::vector<CaptionLine> out;
    constexpr int kMinOverlap = static_cast<int>(2 * kFps);
    for (const auto& [range, line] : c.captions) {
        const int s = std::max(range.first, 0), e = std::min(range.second, frames);
        if (s <= 0 && e >= frames) {
            out.push_back(line);
            continue;
        }  // the whole clip
        const int os = std::max(s, begin), oe = std::min(e, end);
        if (oe - os < kMinOverlap) continue;
        CaptionLine l = line;
        if (!(os == begin && oe == end)) {
            l.start_s = (os - begin) / kFps;
            l.end_s = (oe - begin) / kFps;
        }
        out.push_back(l);
    }
    return out;
}

void write_clip(const std::string& dir, const std::string& id, const JointSequence& joints,
                const std::vector<CaptionLine>& captions, FeatureMatrix& features) {
    features = joints_to_features(joints);
    write_npy(dir + "/new_joint_vecs/" + id + ".npy", feature_matrix_to_array(features));
    write_npy(dir + "/new_joints/" + id + ".npy", joint_sequence_to_array(recover_from_ric(features)));
    std::string text;
    for (const CaptionLine& l : captions) text += format_caption_line(l) + "\n";
    write_file_atomic(dir + "/texts/" + id + ".txt", text);
}

}  // namespace

namespace {

BuildSummary build_into(const BuildOptions& o, const std::string& tmp);

}  // namespace

void BuildOptions::validate() const {
    if (mocap_dir.empty()) throw Error("data build", "--mocap", "a motion-capture folder");
    if (out_dir.empty()) throw Error("data build", "--out", "an output folder");
    // MDM leaves out motions under 40 frames; an hour bounds what a capture take holds (and the frame counts).
    if (!(std::floor(max_seconds * kFps + 1e-9) >= 40 && max_seconds <= 3600))
        throw Error("data build", "--max-seconds", "2 s (40 frames) to 3600 s", std::to_string(max_seconds));
    if (!(max_seconds_per_file >= 0 && max_seconds_per_file <= 86400))
        throw Error("data build", "--max-seconds-per-file", "0 (no cap) to 86400 s",
                    std::to_string(max_seconds_per_file));
    if (derived_kinds.lying_turns && !derive)
        throw Error("data build", "--lying-turns", "the derived clips it is one of (not with --no-derived)");
    if (derived_kinds.lie_down_rests && !derive)
        throw Error("data build", "--lie-down-rests", "the derived clips it is one of (not with --no-derived)");
    if (derived_kinds.turning_walks && !derive)
        throw Error("data build", "--turning-walks", "the derived clips it is one of (not with --no-derived)");
    if (measured_captions < 0 || measured_captions > 20)
        throw Error("data build", "--measured-captions", "0 (none) to 20 captions per clip",
                    std::to_string(measured_captions));
    if (derived_kinds.stairs_round_trips && !derive)
        throw Error("data build", "--stairs-round-trips", "the derived clips it is one of (not with --no-derived)");
}

BuildSummary build_dataset(const BuildOptions& o) {
    o.validate();
    remove_stale_partials(o.out_dir);  // what killed builds left
    const std::string tmp = partial_path_for(o.out_dir);
    try {
        BuildSummary s = build_into(o, tmp);
        publish_partial(tmp, o.out_dir);
        return s;
    } catch (...) {
        std::error_code ignored;
        fs::remove_all(tmp, ignored);  // nothing half-built is left behind
        throw;
    }
}

namespace {

struct TagTally {
    int clips = 0;
    double minutes = 0, captured_minutes = 0;
};

// What the build has written so far.
struct Tally {
    CsvTable clips_csv;
    std::vector<Written> written;
    std::map<std::string, TagTally> per_tag;  // by single tag ("jumping;standing" counts for both)
    int next_id = 0;
    double capture_minutes = 0;  // of the capture-rate copies
    CsvTable captions_csv{
        "captions.csv", {"id", "caption", "source"}, {}};  // every caption line written, and its source
    int measured_captions = 0;
    Tally() {
        clips_csv.header = {"id",
                            "file",
                            "source_dataset",
                            "subject",
                            "licence",
                            "activity_tags",
                            "start_frame",
                            "end_frame",
                            "frames",
                            "mirrored",
                            "provenance",
                            "capture_fps",
                            "capture_start_s",
                            "split"};  // "split" holds the split key until the deal
    }
};

// A derived clip as a recording of its own: captions over the whole clip (`frames` at 20 fps), the source's
// subject, split key and licence (an edit of a clip is bound by the clip's licence), source_dataset "edited".
ClipSource derived_source(const ClipSource& captured, const DerivedClip& d, int frames) {
    ClipSource c;
    c.file = "edited/" + d.method + "/" + captured.file;
    c.subject = captured.subject;
    c.source_dataset = "edited";
    c.licence = captured.licence;
    c.tags = d.activity;
    for (const std::string& caption : d.captions) {
        CaptionLine line;
        line.caption = caption;
        c.captions.push_back({{0, frames}, line});
    }
    c.provenance = {{"derived_from", captured.file},
                    {"source_dataset", captured.source_dataset},
                    {"method", d.method},
                    {"parameters", d.parameters},
                    {"seed", d.seed},
                    {"made_at_fps", d.joints.fps}};
    return c;
}

// The span of a captured recording's capture-rate copy that covers a chunk's new_joints (20 fps frames begin to
// end - 2: features hold one frame fewer than the joints), from the captured frame at or before `begin`, mirrored
// when the chunk is, placed as process_file places the chunk (`clip`, its 20 fps frames as written); and that first
// frame's time after the chunk's, s.
std::pair<JointSequence, double> capture_span(const JointSequence& capture, const JointSequence& clip, int begin,
                                              int end, bool mirror) {
    const double r = capture.fps;
    const int first = static_cast<int>(std::floor(begin / kFps * r + 1e-6));
    const int last = std::min(capture.num_frames - 1, static_cast<int>(std::ceil((end - 2) / kFps * r - 1e-6)));
    const JointSequence span = slice_frames(capture, first, last + 1);
    return {place_like_process_file(mirror ? mirrored(span) : span, clip), first / r - begin / kFps};
}

// Captions measured from a clip's motion (measured_captions.hpp), seeded by its id so a rebuild writes the same.
std::vector<std::string> measured_for(const BuildOptions& o, const JointSequence& clip, const std::string& tags,
                                      const std::string& id) {
    if (o.measured_captions == 0 || clip.num_frames < 3) return {};
    return measured_captions(measure_attributes(clip, id), tags, o.measured_captions, fnv1a64(id));
}

// Cuts one recording into chunks (at most chunks_per_file of them, 0 = all) and writes each, and its mirror;
// with `capture` (the recording at its capture rate), each chunk's capture-rate copy too.
void write_recording(const BuildOptions& o, const std::string& tmp, const ClipSource& c, const std::string& key,
                     const JointSequence& joints, const JointSequence* capture, int max_frames, size_t chunks_per_file,
                     Tally& tally, BuildSummary& summary) {
    for (const auto& [begin, end] : spread(chunks(joints.num_frames, max_frames), chunks_per_file)) {
        const std::vector<CaptionLine> captions = captions_for_chunk(c, begin, end, joints.num_frames);
        if (captions.empty() || end - begin < 2) continue;
        const JointSequence part = slice_frames(joints, begin, end);
        char id[16];
        std::snprintf(id, sizeof id, "%06d", tally.next_id++);
        for (bool mirror : {false, true}) {
            if (mirror && !o.mirror) continue;
            const std::string clip_id = (mirror ? "M" : "") + std::string(id);
            std::vector<CaptionLine> lines = captions;
            if (mirror)
                for (CaptionLine& l : lines) l.caption = swap_left_right(l.caption);
            Written w{clip_id, key, {}};
            const JointSequence clip = mirror ? mirrored(part) : part;
            for (const CaptionLine& l : lines)
                tally.captions_csv.rows.push_back({clip_id, l.caption, c.provenance.is_null() ? "human" : "edited"});
            for (const std::string& caption : measured_for(o, clip, c.tags, clip_id)) {
                lines.push_back(CaptionLine{caption, "", 0, 0});
                tally.captions_csv.rows.push_back({clip_id, caption, "measured"});
                ++tally.measured_captions;
            }
            write_clip(tmp, clip_id, clip, lines, w.features);
            std::string capture_fps, capture_start;
            if (capture) {
                const auto [copy, start_s] = capture_span(*capture, clip, begin, end, mirror);
                write_npy(tmp + "/capture_joints/" + clip_id + ".npy", joint_sequence_to_array(copy));
                capture_fps = decimal(capture->fps), capture_start = decimal(start_s);
                tally.capture_minutes += copy.num_frames / copy.fps / 60.0;
            }
            const double minutes = static_cast<double>(w.features.rows()) / kFps / 60.0;
            summary.minutes += minutes;
            summary.captions += static_cast<int>(lines.size());
            std::stringstream tags(c.tags.empty() ? "untagged" : c.tags);
            std::string tag;
            while (std::getline(tags, tag, ';')) {
                TagTally& t = tally.per_tag[tag];
                t.clips += 1;
                t.minutes += minutes;
                if (c.provenance.is_null()) t.captured_minutes += minutes;
            }
            tally.clips_csv.rows.push_back(
                {clip_id, c.file, c.source_dataset, c.subject, c.licence, c.tags, std::to_string(begin),
                 std::to_string(end), std::to_string(w.features.rows()), mirror ? "1" : "0",
                 c.provenance.is_null() ? "" : c.provenance.dump(), capture_fps, capture_start, key});
            tally.written.push_back(std::move(w));
        }
    }
}

}  // namespace

nlohmann::json train_draw_share(const CsvTable& clips) {
    const size_t tags = clips.column("activity_tags"), split = clips.column("split"), frames = clips.column("frames");
    std::map<std::string, double> count;
    double total = 0;
    for (const auto& row : clips.rows)
        if (row[split] == "train" && Hml3dDataset::usable_length(static_cast<long>(
                                         integer_in(row[frames], 0, 1000000000, clips.source, "frames")))) {
            count[row[tags].empty() ? "untagged" : row[tags]] += 1;
            total += 1;
        }
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [tag, n] : count) out[tag] = n / total;
    return out;
}

namespace {

BuildSummary build_into(const BuildOptions& o, const std::string& tmp) {
    const std::map<std::string, ClipSource> sources = read_sources(o);
    fs::remove_all(tmp);
    for (const char* sub : {"new_joints", "new_joint_vecs", "texts", "capture_joints"})
        fs::create_directories(tmp + "/" + sub);
    const int max_frames = static_cast<int>(std::floor(o.max_seconds * kFps + 1e-9));
    const size_t chunks_per_file =
        o.max_seconds_per_file > 0
            ? static_cast<size_t>(std::max(1.0, std::floor(o.max_seconds_per_file / o.max_seconds)))
            : 0;

    Tally tally;
    nlohmann::json skipped = nlohmann::json::array();
    BuildSummary summary;
    DeriveReport derive_report;
    Progress progress("data build", sources.size(), "files");
    for (const auto& [file, c] : sources) {
        progress.advance();
        if (c.captions.empty()) continue;
        if (!o.licences.empty() && !o.licences.count(c.source_dataset)) continue;
        JointSequence joints;
        std::optional<JointSequence> capture;
        try {
            joints = import_motion(o.mocap_dir + "/" + file);
            if (o.capture_rate) capture = import_at_capture_rate(o.mocap_dir + "/" + file);
        } catch (const Error& e) {
            if (o.strict) throw;
            skipped.push_back({{"file", file}, {"reason", e.what()}});
            ++summary.skipped_files;
            continue;
        }
        const std::string key = split_key(c);
        write_recording(o, tmp, c, key, joints, capture ? &*capture : nullptr, max_frames, chunks_per_file, tally,
                        summary);
        if (!o.derive) continue;
        // Derived at the capture rate where there is one; the dataset holds them at 20 fps, with the
        // capture-rate clip as their copy for the sensors.
        for (DerivedClip& d : derive_clips(capture ? *capture : joints, c.tags, file, derive_report, o.derived_kinds))
            write_recording(o, tmp, derived_source(c, d, d.joints_20fps.num_frames), key, d.joints_20fps,
                            capture ? &d.joints : nullptr, max_frames, chunks_per_file, tally, summary);
    }
    if (tally.written.empty()) throw Error(o.out_dir, "clips", "at least one clip with a caption after filtering");
    summary.clips = static_cast<int>(tally.written.size());
    std::vector<Written>& written = tally.written;
    CsvTable& clips_csv = tally.clips_csv;

    std::map<std::string, int> clips_per_key;
    for (const Written& w : written) ++clips_per_key[w.split_key];
    const std::map<std::string, Split> splits = assign_splits(clips_per_key);
    std::vector<FeatureMatrix> all;
    std::map<Split, std::string> lists;
    std::string all_ids;
    for (const Written& w : written) {
        all.push_back(w.features);
        lists[splits.at(w.split_key)] += w.id + "\n";
        all_ids += w.id + "\n";
    }
    for (auto& row : clips_csv.rows) row.back() = split_name(splits.at(row.back()));
    const FeatureStats stats = compute_mean_std(all);
    std::vector<float> mean(stats.mean.data(), stats.mean.data() + stats.mean.size()),
        std(stats.std.data(), stats.std.data() + stats.std.size());
    write_npy(tmp + "/Mean.npy", NdArray::from(mean, {static_cast<int64_t>(mean.size())}));
    write_npy(tmp + "/Std.npy", NdArray::from(std, {static_cast<int64_t>(std.size())}));
    for (Split s : {Split::train, Split::val, Split::test})
        write_file_atomic(tmp + "/" + split_name(s) + ".txt", lists[s]);
    write_file_atomic(tmp + "/all.txt", all_ids);
    write_csv(tmp + "/clips.csv", clips_csv);
    write_csv(tmp + "/captions.csv", tally.captions_csv);

    nlohmann::json j;
    j["clips"] = summary.clips;
    j["minutes"] = summary.minutes;
    j["captions"] = summary.captions;
    j["measured_captions"] = tally.measured_captions;
    j["mirrored"] = o.mirror;
    j["skipped_files"] = skipped;
    for (const auto& [tag, v] : tally.per_tag)
        j["per_activity_tag"][tag] = {{"clips", v.clips},
                                      {"minutes", v.minutes},
                                      {"captured_minutes", v.captured_minutes},
                                      {"derived_minutes", v.minutes - v.captured_minutes}};
    j["derived"] = {{"included", o.derive},
                    {"lying_turns", o.derive && o.derived_kinds.lying_turns},
                    {"stairs_round_trips", o.derive && o.derived_kinds.stairs_round_trips},
                    {"lie_down_rests", o.derive && o.derived_kinds.lie_down_rests},
                    {"turning_walks", o.derive && o.derived_kinds.turning_walks},
                    {"edits_refused", derive_report.refused},
                    {"failed_quality", derive_report.failed_quality}};
    j["train_draw_share"] = train_draw_share(clips_csv);
    j["capture_rate"] = {{"included", o.capture_rate}, {"minutes", tally.capture_minutes}};
    for (Split s : {Split::train, Split::val, Split::test})
        j["split_clips"][split_name(s)] = std::count(lists[s].begin(), lists[s].end(), '\n');
    summary.json = j.dump(1);
    write_file_atomic(tmp + "/summary.json", summary.json + "\n");
    return summary;
}

}  // namespace

}  // namespace t2imu
