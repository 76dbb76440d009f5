#include "pipeline/motion_source.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <random>
#include <sstream>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/hash.hpp"
#include "core/json_file.hpp"
#include "core/npy.hpp"
#include "core/parse.hpp"
#include "data/clip_activities.hpp"
#include "data/hml3d_dataset.hpp"
#include "data/measured_captions.hpp"
#include "motion/activity_names.hpp"
#include "motion/gait_splice.hpp"
#include "motion/humanml3d.hpp"
#include "motion/motion_activity.hpp"
#include "motion/resample.hpp"
#include "motion/velocity_fusion.hpp"
#include "text/sentence_similarity.hpp"

namespace t2imu {

namespace {

class DiffusionSource : public MotionSource {
public:
    DiffusionSource(const std::string& dir, const SampleOptions& sampling, const std::string& device)
        : dir_(dir), sampling_(sampling), model_(load_motion_model(dir, device)) {
        model_->caption_anchor_weight(sampling_.caption_anchor);  // refused here, before a synthesis writes anything
    }

    // With stairs_round_trips, a prompt asking for stairs both ways draws an ascent and a descent of the asked length
    // each (the model's shorter descents stand at the top of the flight: docs/results.md; the descent from its
    // seed's splitmix), joined at a stance and cut to the length around the join (gait_splice.hpp); a pair with no
    // stance to join at is drawn as without it.
    std::vector<JointSequence> generate(const std::vector<std::string>& prompts,
                                        const std::vector<std::string>& activities, const std::vector<uint64_t>& seeds,
                                        int frames) override {
        records_.assign(prompts.size(), nullptr);
        if (!sampling_.stairs_round_trips) return generate_from(prompts, activities, seeds, frames, {}, 1.0);
        std::vector<Draw> halves;
        std::vector<size_t> trips, whole;
        for (size_t i = 0; i < prompts.size(); ++i) {
            const std::string activity = activities.empty() ? "" : activities[i];
            if (activity_asked(activity, prompts[i]) != "stairs") {
                whole.push_back(i);
                continue;
            }
            trips.push_back(i);
            halves.push_back({prompts[i], "stairs_up", seeds[i]});
            halves.push_back({prompts[i], "stairs_down", splitmix64(seeds[i])});
        }
        std::vector<JointSequence> out(prompts.size());
        const std::vector<JointSequence> drawn_halves = draw(halves, frames);
        GaitSpliceOptions join;
        join.contact_smoothing_s = kRoundTripContactSmoothingS;
        for (size_t k = 0; k < trips.size(); ++k) {
            try {
                GaitSplice trip = splice_to_length(drawn_halves[2 * k], drawn_halves[2 * k + 1], frames, join);
                out[trips[k]] = std::move(trip.motion);
                records_[trips[k]] = {{"round_trip", {{"joined", true}, {"splice_frame", trip.splice_frame}}}};
            } catch (const Error& e) {
                whole.push_back(trips[k]);
                records_[trips[k]] = {{"round_trip", {{"joined", false}, {"why", e.what()}}}};
            }
        }
        std::vector<Draw> whole_draws;
        for (size_t i : whole) whole_draws.push_back({prompts[i], activities.empty() ? "" : activities[i], seeds[i]});
        std::vector<JointSequence> drawn = draw(whole_draws, frames);
        for (size_t k = 0; k < whole.size(); ++k) out[whole[k]] = std::move(drawn[k]);
        return out;
    }

    nlohmann::json draw_record(size_t i) const override { return i < records_.size() ? records_[i] : nlohmann::json(); }

    // From noised start motions (the hybrid), or from pure noise when `starts` is empty. The activity asked
    // (the label, else the prompt's words) chooses the captions of the model's caption anchor.
    std::vector<JointSequence> generate_from(const std::vector<std::string>& prompts,
                                             const std::vector<std::string>& activities,
                                             const std::vector<uint64_t>& seeds, int frames,
                                             std::vector<FeatureMatrix> starts, double strength) {
        SampleOptions o = sampling_;
        o.frames = frames;
        o.seeds = seeds;
        o.activities.clear();
        for (size_t i = 0; i < prompts.size(); ++i)
            o.activities.push_back(activity_asked(activities.empty() ? "" : activities[i], prompts[i]));
        o.start_motions = std::move(starts);
        o.strength = strength;
        std::vector<JointSequence> out;
        for (const FeatureMatrix& f : sample_motions(*model_, prompts, o))
            out.push_back(joints_from_features(f, o.height_crossover_hz));
        return out;
    }

    nlohmann::json describe() const override {
        nlohmann::json d = {
            {"kind", "diffusion"},
            {"model", dir_},
            {"training_step", model_->meta.value("training", nlohmann::json::object()).value("step", 0)},
            {"sampler", sampler_name(sampling_.sampler)},
            {"steps", denoiser_calls(sampling_.sampler, sampling_.steps, model_->schedule.steps)},
            {"guidance", sampling_.guidance},
            {"eta", sampling_.eta},
            {"caption_anchor", model_->caption_anchor_weight(sampling_.caption_anchor)},
            {"caption_anchor_neighbours", model_->anchor.neighbours}};
        // Absent when off, so folders made before them resume.
        if (sampling_.height_crossover_hz > 0) d["height_crossover_hz"] = sampling_.height_crossover_hz;
        if (sampling_.stairs_round_trips) d["stairs_round_trips"] = true;
        return d;
    }

    const CaptionIndex* caption_index() const override { return model_->anchor.index.get(); }

private:
    struct Draw {  // one motion asked of generate_from
        std::string prompt, activity;
        uint64_t seed;
    };

    std::vector<JointSequence> draw(const std::vector<Draw>& draws, int frames) {
        if (draws.empty()) return {};
        std::vector<std::string> prompts, activities;
        std::vector<uint64_t> seeds;
        for (const Draw& d : draws) {
            prompts.push_back(d.prompt);
            activities.push_back(d.activity);
            seeds.push_back(d.seed);
        }
        return generate_from(prompts, activities, seeds, frames, {}, 1.0);
    }

    std::string dir_;
    SampleOptions sampling_;
    std::unique_ptr<MotionModel> model_;
    std::vector<nlohmann::json> records_;  // per motion of the last generate(): a round trip's join
};

// Joint positions at time t * factor of the source for every output frame, linearly interpolated (20 fps).
JointSequence time_warp(const JointSequence& m, double factor) {
    const int frames = std::max(1, static_cast<int>(std::floor((m.num_frames - 1) / factor)) + 1);
    JointSequence out(frames, m.num_joints, m.fps);
    for (int f = 0; f < frames; ++f) {
        const double s = std::min(f * factor, static_cast<double>(m.num_frames - 1));
        const int a = static_cast<int>(std::floor(s));
        const int b = std::min(a + 1, m.num_frames - 1);
        const double w = s - a;
        for (int j = 0; j < m.num_joints; ++j) out.at(f, j) = (1 - w) * m.at(a, j) + w * m.at(b, j);
    }
    return out;
}

std::string default_vocab() {
    if (const char* env = std::getenv("T2IMU_VOCAB"); env && std::filesystem::exists(env)) return env;
    return "cache/text/glove-100k.safetensors";
}

// A captured clip's copy at its capture rate (dataset_builder.hpp: capture_joints/ and clips.csv).
struct CaptureCopy {
    double fps = 0;
    double start_s = 0;  // its first frame's time after the clip's first frame, s
};

// Whether DATASET was built with measured captions (summary.json's measured_captions above 0): only then do its
// captions name attributes often enough to rank by them. Over a build without them, "slowly" would send every such
// prompt to the few clips whose human caption says so (the caption anchor did that to models/default).
bool has_measured_captions(const std::string& dataset) {
    const std::string path = dataset + "/summary.json";
    if (!std::filesystem::exists(path)) return false;
    const nlohmann::json summary = read_json_file(path);
    return summary.is_object() && summary.contains("measured_captions") &&
           summary.at("measured_captions").is_number() && summary.at("measured_captions").get<double>() > 0;
}

// Every copy clips.csv names, checked before any draw: its rate positive, its start within one capture frame
// before the clip's, its file present.
std::map<std::string, CaptureCopy> capture_copies(const std::string& dataset) {
    std::map<std::string, CaptureCopy> out;
    const std::string path = dataset + "/clips.csv";
    if (!std::filesystem::exists(path)) return out;
    const CsvTable t = read_csv(path);
    if (!t.has_column("capture_fps")) return out;  // a dataset built before capture-rate copies existed
    const size_t id = t.column("id"), fps = t.column("capture_fps"), start = t.column("capture_start_s");
    for (size_t r = 0; r < t.rows.size(); ++r) {
        if (t.rows[r][fps].empty()) continue;
        const CaptureCopy c{t.number(r, fps), t.number(r, start)};
        const std::string row = path + " row " + t.rows[r][id];
        if (!(c.fps > 0 && c.fps <= 1000)) throw Error(row, "capture_fps", "a frame rate in (0, 1000]", t.rows[r][fps]);
        if (!(c.start_s > -1 / c.fps - 1e-9 && c.start_s <= 1e-9))
            throw Error(row, "capture_start_s",
                        "within one capture frame before the clip's start, in (-1/capture_fps, 0]", t.rows[r][start]);
        const std::string file = dataset + "/capture_joints/" + t.rows[r][id] + ".npy";
        if (!std::filesystem::exists(file))
            throw Error(file, "capture_joints", "the capture-rate copy clips.csv names (t2imu data build)");
        out[t.rows[r][id]] = c;
    }
    return out;
}

// The frames of `copy` (at copy.fps) that show what the 20 fps draw shows: span frames a.. of the clip, time-warped
// by `factor` and cropped from warped frame `start`, `frames` long. Output frame g, at g / fps s into the draw,
// shows the clip at (a + (start + g 20 / fps) factor) / 20 s. The last frame is at or after the draw's last, less
// than a capture frame later, so the recordings are not shorter than the 20 fps ones; where that passes the copy's
// end (at or after the clip's, dataset_builder.hpp), it holds the copy's last frame.
JointSequence capture_rate_crop(const JointSequence& copy, const CaptureCopy& c, int a, double factor, int start,
                                int frames) {
    const int n = static_cast<int>(std::ceil((frames - 1) * c.fps / 20.0 - 1e-6)) + 1;
    JointSequence out(n, copy.num_joints, c.fps);
    for (int g = 0; g < n; ++g) {
        const double clip_s = (a + (start + g * 20.0 / c.fps) * factor) / 20.0;
        interpolate_frame(copy, (clip_s - c.start_s) * c.fps, out, g);
    }
    return out;
}

// "000123#40-120" -> 40: the first 20 fps frame of a caption span within its clip (0 for a whole clip).
int span_start(const std::string& id) {
    const size_t hash = id.find('#');
    if (hash == std::string::npos) return 0;
    const size_t dash = id.find('-', hash);  // "40-120": the span's first frame before the dash
    return static_cast<int>(
        integer_in(id.substr(hash + 1, dash == std::string::npos ? std::string::npos : dash - hash - 1), 0, 1000000, id,
                   "span start"));
}

enum class Tier { tags_and_classifier, tags, any };
const char* tier_name(Tier t) {
    return t == Tier::tags_and_classifier ? "tags+classifier" : t == Tier::tags ? "tags" : "any";
}

class RetrievalSource : public MotionSource {
public:
    RetrievalSource(const std::string& dataset, const std::string& vocab, const std::string& activity_reference)
        : dataset_(dataset),
          vocab_(WordVectors::load(vocab.empty() ? default_vocab() : vocab)),
          sif_(vocab_, 1e-4),
          clips_(Hml3dDataset(dataset, "train").clips()),
          capture_(capture_copies(dataset)),
          match_attributes_(has_measured_captions(dataset)) {
        if (clips_.empty()) throw Error(dataset, "train split", "at least one clip to retrieve");
        const auto tags = read_clip_activities(dataset);
        std::optional<MotionActivityClassifier> classifier;
        if (!activity_reference.empty()) classifier = MotionActivityClassifier::load(activity_reference);
        for (const MotionClip& c : clips_) {
            std::vector<Eigen::VectorXd> e;
            std::vector<std::vector<std::string>> named;
            for (const CaptionLine& l : c.captions)
                e.push_back(sif_.embed(l.caption)), named.push_back(attributes_asked(l.caption));
            caption_embeddings_.push_back(std::move(e));
            caption_attributes_.push_back(std::move(named));
            const auto t = tags.find(clip_file_id(c.id));
            tags_.push_back(t == tags.end() ? std::vector<std::string>{} : t->second);
            shown_.push_back(classifier ? classifier->classify(describe_motion(recover_from_ric(c.features))).best
                                        : "");
        }
        if (classifier) classes_ = classifier->classes();
        std::vector<Prompt> captions;  // each caption under each of its clip's activities, for coverage
        for (size_t i = 0; i < clips_.size(); ++i)
            for (const CaptionLine& l : clips_[i].captions)
                for (const std::string& tag : tags_[i].empty() ? std::vector<std::string>{"other"} : tags_[i])
                    captions.push_back({tag, l.caption});
        index_ = std::make_unique<CaptionIndex>(vocab_, captions, dataset);
    }

    const CaptionIndex* caption_index() const override { return index_.get(); }

    std::vector<JointSequence> generate(const std::vector<std::string>& prompts,
                                        const std::vector<std::string>& activities, const std::vector<uint64_t>& seeds,
                                        int frames) override {
        if (seeds.size() != prompts.size() || activities.size() != prompts.size())
            throw Error("retrieval", "seeds, activities", "one per prompt");
        std::vector<JointSequence> out;
        records_.clear();
        capture_rate_.clear();
        for (size_t i = 0; i < prompts.size(); ++i) {
            std::mt19937_64 rng(seeds[i]);
            const std::string asked = activity_asked(activities[i], prompts[i]);
            Tier tier = Tier::any;
            const std::vector<size_t> best = nearest_clips(prompts[i], candidates(asked, &tier));
            const size_t pick = best[std::uniform_int_distribution<size_t>(0, best.size() - 1)(rng)];
            const double factor = std::uniform_real_distribution<double>(1 - kRetrievalWarp, 1 + kRetrievalWarp)(rng);
            const JointSequence warped = time_warp(recover_from_ric(clips_[pick].features), factor);
            const int n = std::min(frames, warped.num_frames);
            const int start = std::uniform_int_distribution<int>(0, warped.num_frames - n)(rng);
            out.push_back(slice_frames(warped, start, start + n));
            capture_rate_.push_back(capture_rate_draw(clips_[pick].id, factor, start, n));
            records_.push_back({{"clip", clips_[pick].id},
                                {"tags", tags_[pick]},
                                {"classifier", shown_[pick]},
                                {"activity_asked", asked},
                                {"tier", tier_name(tier)},
                                {"tags_show_activity", tagged(pick, asked)}});
        }
        return out;
    }

    nlohmann::json describe() const override {
        return {{"kind", "retrieval"},
                {"dataset", dataset_},
                {"split", "train"},
                {"clips", clips_.size()},
                {"top_k", kRetrievalTopK},
                {"time_warp", kRetrievalWarp},
                {"activity_classifier", !classes_.empty()},
                {"match_attributes", match_attributes_}};
    }

    nlohmann::json draw_record(size_t i) const override { return i < records_.size() ? records_[i] : nlohmann::json(); }

    std::optional<JointSequence> capture_rate_motion(size_t i) const override {
        return i < capture_rate_.size() ? capture_rate_[i] : std::nullopt;
    }

private:
    std::optional<JointSequence> capture_rate_draw(const std::string& id, double factor, int start, int frames) const {
        const auto c = capture_.find(clip_file_id(id));
        if (c == capture_.end()) return std::nullopt;
        const std::string path = dataset_ + "/capture_joints/" + c->first + ".npy";
        const JointSequence copy = joint_sequence_from_array(read_npy(path), path, 22, 1, c->second.fps);
        return capture_rate_crop(copy, c->second, span_start(id), factor, start, frames);
    }

    bool tagged(size_t c, const std::string& asked) const {
        for (const std::string& t : tags_[c])
            if (shows_activity(t, asked)) return true;
        return false;
    }

    // Whether the classifier can judge the activity (no classifier, or no class for a gesture: it cannot).
    bool checkable(const std::string& asked) const {
        for (const std::string& k : classes_)
            if (shows_activity(k, asked)) return true;
        return false;
    }

    // The first non-empty tier of clips for the asked activity (see the header).
    std::vector<size_t> candidates(const std::string& asked, Tier* tier) const {
        std::vector<size_t> both, tags_only, all;
        const bool judged = checkable(asked);
        for (size_t c = 0; c < clips_.size(); ++c) {
            all.push_back(c);
            if (asked.empty() || !tagged(c, asked)) continue;
            tags_only.push_back(c);
            if (judged && shows_activity(shown_[c], asked)) both.push_back(c);
        }
        if (!both.empty()) {
            *tier = Tier::tags_and_classifier;
            return both;
        }
        if (!tags_only.empty()) {
            *tier = Tier::tags;
            return tags_only;
        }
        *tier = Tier::any;
        return all;
    }

    // Clips by their best caption: the most of the prompt's attributes named, then the most similar (as the caption
    // anchor ranks, text/caption_index.hpp).
    std::vector<size_t> nearest_clips(const std::string& prompt, const std::vector<size_t>& candidates) const {
        const Eigen::VectorXd p = sif_.embed(prompt);
        const std::vector<std::string> asked =
            match_attributes_ ? attributes_asked(prompt) : std::vector<std::string>{};
        struct Scored {
            size_t shared;
            double similarity;
            size_t clip;
        };
        std::vector<Scored> scored;
        for (size_t c : candidates) {
            Scored best{0, -2, c};
            for (size_t j = 0; j < caption_embeddings_[c].size(); ++j) {
                const Scored s{attributes_shared(asked, caption_attributes_[c][j]),
                               cosine_similarity(p, caption_embeddings_[c][j]), c};
                if (s.shared > best.shared || (s.shared == best.shared && s.similarity > best.similarity)) best = s;
            }
            scored.push_back(best);
        }
        const auto better = [](const Scored& a, const Scored& b) {
            if (a.shared != b.shared) return a.shared > b.shared;
            return a.similarity != b.similarity ? a.similarity > b.similarity : a.clip < b.clip;
        };
        std::sort(scored.begin(), scored.end(), better);
        // The k best and every clip as good as the k-th (identical captions embed identically).
        size_t k = std::min<size_t>(kRetrievalTopK, scored.size());
        while (k < scored.size() && scored[k].shared == scored[k - 1].shared &&
               scored[k].similarity >= scored[k - 1].similarity - 1e-9)
            ++k;
        std::vector<size_t> out;
        for (size_t i = 0; i < k; ++i) out.push_back(scored[i].clip);
        return out;
    }

    std::string dataset_;
    WordVectors vocab_;
    SifEncoder sif_;
    std::vector<MotionClip> clips_;
    std::vector<std::vector<Eigen::VectorXd>> caption_embeddings_;
    std::vector<std::vector<std::vector<std::string>>>
        caption_attributes_;                                  // per clip, per caption: the attributes it names
    std::vector<std::vector<std::string>> tags_;              // canonical activity names per clip
    std::vector<std::string> shown_;                          // the classifier's class per clip ("" without one)
    std::vector<std::string> classes_;                        // the classifier's classes (empty without one)
    std::unique_ptr<CaptionIndex> index_;                     // every caption under its clip's activities
    std::map<std::string, CaptureCopy> capture_;              // by clip file id: the clips with a capture-rate copy
    bool match_attributes_ = false;                           // rank by attribute words first (has_measured_captions)
    std::vector<nlohmann::json> records_;                     // per motion of the last generate()
    std::vector<std::optional<JointSequence>> capture_rate_;  // likewise
};

// Retrieval, then the model: each prompt's retrieved clip (HumanML3D features, `frames` long; a shorter clip
// holds its last frame) noised to strength s and denoised with the prompt (SampleOptions::start_motions).
class HybridSource : public MotionSource {
public:
    HybridSource(const std::string& model, const std::string& dataset, double strength, const SampleOptions& sampling,
                 const std::string& device, const std::string& vocab, const std::string& activity_reference)
        : retrieval_(dataset, vocab, activity_reference), diffusion_(model, sampling, device), strength_(strength) {}

    std::vector<JointSequence> generate(const std::vector<std::string>& prompts,
                                        const std::vector<std::string>& activities, const std::vector<uint64_t>& seeds,
                                        int frames) override {
        std::vector<FeatureMatrix> starts;
        for (const JointSequence& clip : retrieval_.generate(prompts, activities, seeds, frames + 1)) {
            const FeatureMatrix f = joints_to_features(clip);  // one row fewer than the joints
            FeatureMatrix start(frames, 263);
            for (int r = 0; r < frames; ++r) start.row(r) = f.row(std::min<Eigen::Index>(r, f.rows() - 1));
            starts.push_back(std::move(start));
        }
        return diffusion_.generate_from(prompts, activities, seeds, frames, starts, strength_);
    }

    nlohmann::json describe() const override {
        nlohmann::json d = diffusion_.describe();
        d["kind"] = "hybrid";
        d["strength"] = strength_;
        d["retrieval"] = retrieval_.describe();
        return d;
    }

    nlohmann::json draw_record(size_t i) const override { return retrieval_.draw_record(i); }
    const CaptionIndex* caption_index() const override { return diffusion_.caption_index(); }

private:
    RetrievalSource retrieval_;
    DiffusionSource diffusion_;
    double strength_;
};

}  // namespace

std::unique_ptr<MotionSource> open_motion_source(const MotionSourceSpec& spec, const SampleOptions& sampling,
                                                 const std::string& device, const std::string& vocab,
                                                 const std::string& activity_reference) {
    if (const auto* r = std::get_if<RetrievalSpec>(&spec))
        return std::make_unique<RetrievalSource>(r->dataset, vocab, activity_reference);
    if (const auto* h = std::get_if<HybridSpec>(&spec))
        return std::make_unique<HybridSource>(h->model_folder, h->dataset, h->strength, sampling, device, vocab,
                                              activity_reference);
    return std::make_unique<DiffusionSource>(std::get<ModelFolderSpec>(spec).folder, sampling, device);
}

}  // namespace t2imu
