#include "pipeline/synth.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>

#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/json_file.hpp"
#include "core/npy.hpp"
#include "core/output_path.hpp"
#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "imu/imu_dataset.hpp"
#include "imu/synth_folder.hpp"
#include "imu/virtual_imu.hpp"
#include "motion/activity_names.hpp"
#include "motion/bvh_export.hpp"
#include "motion/motion_activity.hpp"
#include "motion/normalization.hpp"
#include "pipeline/motion_source.hpp"
#include "text/prompt_coverage.hpp"
#include "text/prompt_set.hpp"

namespace t2imu {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using nlohmann::json;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// A job's motion after the quality filter: the attempt kept, or the last one when every attempt failed.
struct Drawn {
    JointSequence joints;
    std::optional<JointSequence> sensor_joints;  // what the sensors see when not `joints` (the capture-rate copy)
    uint64_t seed = 0;
    MotionQuality quality;
    std::vector<std::string> failures;  // of the kept (or last) attempt
    std::string activity_shown;         // the activity classifier's answer ("" without a check)
    double activity_agreement = 1;
    std::vector<MarkerAttempt> attempts;  // seed and failures of every attempt
    json source;                          // the source's record of the draw (retrieval: the clip), or null
    bool kept = true;
};

uint64_t attempt_seed(const SynthOptions& o, int job, int attempt) {
    return o.sampling.seed + static_cast<uint64_t>(job) + static_cast<uint64_t>(attempt) * kSeedStridePerAttempt;
}

// The activity check of a drawn motion: a failure when the motion shows something far from the prompt's activity.
void check_activity(const MotionActivityClassifier& classifier, const std::string& expected, double min_agreement,
                    Drawn& d) {
    const ActivityScores s = classifier.classify(describe_motion(d.joints));
    d.activity_shown = s.best;
    d.activity_agreement = s.agreement(expected);
    if (d.activity_agreement < min_agreement) d.failures.push_back("activity");
}

bool fails_only_activity(const Drawn& d) { return d.failures.size() == 1 && d.failures[0] == "activity"; }

// Of a job's draws that fail nothing but the activity check, the one agreeing best with the prompt's activity.
// Keeping it (rather than dropping the job) keeps every activity's share of the data: dropping starves exactly
// the activities the model renders worst.
void keep_best_activity_draw(Drawn& d, std::optional<Drawn>& best) {
    if (!best) return;
    best->attempts = d.attempts;
    best->kept = true;
    d = std::move(*best);
}

// Draws every job of the batch, then again with the next seed those the filter rejects. `expected`: per job, the
// activity classifier's class for its prompt ("" = not checked).
std::vector<Drawn> draw_filtered(MotionSource& source, const std::vector<int>& jobs,
                                 const std::vector<std::string>& texts, const std::vector<std::string>& labels,
                                 const std::vector<std::string>& expected, const MotionActivityClassifier* classifier,
                                 const SynthPlan& plan, double* generate_s, double* score_s) {
    const SynthOptions& o = plan.options;
    std::vector<Drawn> out(jobs.size());
    std::vector<std::optional<Drawn>> best_activity(jobs.size());  // see keep_best_activity_draw
    std::vector<size_t> pending(jobs.size());
    for (size_t i = 0; i < jobs.size(); ++i) pending[i] = i;
    for (int attempt = 0; !pending.empty(); ++attempt) {
        std::vector<std::string> prompts, activities;
        std::vector<uint64_t> seeds;
        for (size_t i : pending) {
            prompts.push_back(texts[i]);
            activities.push_back(labels[i]);
            seeds.push_back(attempt_seed(o, jobs[i], attempt));
        }
        auto t0 = Clock::now();
        std::vector<JointSequence> motions = source.generate(prompts, activities, seeds, plan.frames);
        *generate_s += since(t0);
        t0 = Clock::now();
        std::vector<size_t> again;
        for (size_t p = 0; p < pending.size(); ++p) {
            Drawn& d = out[pending[p]];
            d.joints = std::move(motions[p]);
            place_on_floor(d.joints);
            d.seed = seeds[p];
            d.source = source.draw_record(p);
            d.sensor_joints = o.capture_rate ? source.capture_rate_motion(p) : std::nullopt;
            if (d.sensor_joints) place_on_floor(*d.sensor_joints);
            d.quality = score_motion(d.joints);
            d.failures = quality_failures(d.quality, o.thresholds);
            if (classifier) check_activity(*classifier, expected[pending[p]], o.min_activity_agreement, d);
            d.attempts.push_back(
                {d.seed, d.failures, classifier ? std::optional<double>(d.activity_agreement) : std::nullopt});
            d.kept = !o.filter || d.failures.empty();
            std::optional<Drawn>& best = best_activity[pending[p]];
            if (!d.kept && fails_only_activity(d) && (!best || d.activity_agreement > best->activity_agreement))
                best = d;
            if (!d.kept && attempt < o.max_retries)
                again.push_back(pending[p]);
            else if (!d.kept && !o.drop_activity_failures)
                keep_best_activity_draw(d, best);
        }
        *score_s += since(t0);
        pending = again;
    }
    return out;
}

// The sampling batches: consecutive job indices in groups of `batch` counted from job 0, cut at the shard's ends.
// A group with any job left to do is drawn whole, so that every job comes from the same batch composition on
// every run of the same settings: batched matrix products round by composition (~1e-4 m/s^2 at the sensors), and
// a resumed run must write the bytes an uninterrupted one would.
std::vector<std::vector<int>> job_groups(int first, int last, int batch) {
    std::vector<std::vector<int>> out;
    const int size = std::max(1, batch);
    for (int g = first - first % size; g < last; g += size) {
        out.emplace_back();
        for (int k = std::max(g, first); k < std::min(g + size, last); ++k) out.back().push_back(k);
    }
    return out;
}

std::map<std::string, double> quality_map(const MotionQuality& q) {
    const auto scores = quality_scores(q);
    std::map<std::string, double> out;
    for (size_t i = 0; i < kNumQualityScores; ++i) out[kQualityScoreNames[i]] = scores[i];
    return out;
}

// Writes the job's motion and recordings, then its marker (last: the job is done).
// A job redone after a kill starts clean: the recordings and the temporaries (".<name>....tmpPID", core/
// atomic_file.hpp) its killed attempt left go, so the folder ends as an uninterrupted run leaves it.
void clear_job_outputs(const std::string& out, const std::string& name) {
    std::error_code ignored;
    fs::remove_all(out + "/" + job_recordings_dir(name), ignored);
    if (!fs::is_directory(out + "/motions")) return;
    for (const auto& e : fs::directory_iterator(out + "/motions"))
        if (e.path().filename().string().rfind("." + name, 0) == 0) fs::remove(e.path(), ignored);
}

void write_job(const SynthPlan& plan, int job, const Prompt& prompt, const std::optional<MarkerCoverage>& coverage,
               int sample, const Drawn& d) {
    const SynthOptions& o = plan.options;
    const std::string name = job_name(job);
    clear_job_outputs(o.out, name);
    JobMarker marker;
    marker.coverage = coverage;
    marker.job = name, marker.index = job, marker.sample = sample, marker.frames = d.joints.num_frames;
    marker.prompt = prompt.text, marker.activity = prompt.activity;
    marker.seed = d.seed, marker.attempts = d.attempts, marker.quality = quality_map(d.quality), marker.kept = d.kept;
    if (d.sensor_joints) marker.sensor_motion_fps = d.sensor_joints->fps;
    marker.source_draw = d.source;
    if (!d.activity_shown.empty())
        marker.activity_check =
            ActivityCheck{d.activity_shown, d.activity_agreement, d.activity_agreement >= o.min_activity_agreement};
    if (d.kept) {
        write_npy(o.out + "/" + job_joints_file(name), joint_sequence_to_array(d.joints));
        write_bvh(o.out + "/" + job_bvh_file(name), smpl22_to_bvh(d.joints));
        marker.motions.emplace();
        for (const std::string& file : {job_joints_file(name), job_bvh_file(name)})
            marker.motions->push_back({file, static_cast<int64_t>(fs::file_size(o.out + "/" + file))});
        VirtualImuOptions imu = plan.imu;
        imu.seed = plan.imu.seed + static_cast<uint64_t>(job);
        for (const BodySpec& b : plan.bodies) {
            const BodyImu r = synthesize_body_imu(d.sensor_joints ? *d.sensor_joints : d.joints, b, plan.sensors, imu);
            const std::vector<std::string> files = write_body_imu(o.out + "/" + job_recordings_dir(name), r);
            for (size_t s = 0; s < r.mounts.size(); ++s) {
                const std::string path = job_recordings_dir(name) + "/" + files[s];
                marker.recordings.push_back({path, r.body.name, r.mounts[s].placement.position, r.signals[s].t.size(),
                                             static_cast<int64_t>(fs::file_size(o.out + "/" + path)), r.tempo,
                                             r.mount_tilts_deg[s]});
            }
        }
    }
    write_job_marker(o.out, marker);
}

// Whether the file `out`/`relative` exists with `bytes` bytes (any size when the marker predates sizes: -1).
bool file_whole(const std::string& out, const std::string& relative, int64_t bytes) {
    std::error_code ec;
    const uintmax_t size = fs::file_size(out + "/" + relative, ec);
    return !ec && (bytes < 0 || size == static_cast<uintmax_t>(bytes));
}

// Whether job `job` is finished and whole: its marker reads and holds every field later stages need, each
// recording and motion file it lists exists with the size it was written with (markers from before sizes or
// motion lists were recorded: the files exist). A resume redoes a job whose marker is damaged or whose files
// went missing or were cut short (a full disk, a copy that broke off, a motion deleted by hand).
bool job_intact(const std::string& out, int job) {
    const std::string path = job_marker_path(out, job_name(job));
    if (!fs::exists(path)) return false;
    JobMarker marker;
    try {
        marker = read_job_marker(path);
    } catch (const Error&) {
        return false;  // damaged: the job is redone and its marker rewritten
    }
    for (const MarkerRecording& r : marker.recordings)
        if (!file_whole(out, r.path, r.bytes)) return false;
    if (!marker.kept) return true;
    if (marker.motions) {
        for (const MarkerFile& m : *marker.motions)
            if (!file_whole(out, m.path, m.bytes)) return false;
        return true;
    }
    const std::string name = job_name(job);
    return file_whole(out, job_joints_file(name), -1) && file_whole(out, job_bvh_file(name), -1);
}

json settings_json(const SynthPlan& plan, const json& source) {
    const SynthOptions& o = plan.options;
    json p = json::array();
    for (const Prompt& x : plan.prompts) p.push_back({x.activity, x.text});
    json s = {{"prompts_file", o.prompts},
              {"prompts", p},
              {"samples_per_prompt", o.samples_per_prompt},
              {"source", source},
              {"seed", o.sampling.seed},
              {"seconds", o.seconds},
              {"bodies", o.bodies},
              {"sensors", o.sensors},
              {"rate_hz", o.rate_hz},
              {"placed_on_floor", true},
              {"filter", o.filter},
              {"max_retries", o.max_retries},
              {"thresholds", quality_limits(o.thresholds)}};
    if (o.realism != "none") s["realism"] = plan.imu.realism().to_json();  // absent: folders from before it stay valid
    if (o.capture_rate) s["capture_rate"] = true;                          // likewise
    // placed_on_floor is always true: it makes a resume refuse folders drawn before floor placement existed.
    // activity_check is absent without a check, so folders made before the check existed stay valid.
    if (!o.activity_reference.empty())
        s["activity_check"] = {{"reference", o.activity_reference},
                               {"min_agreement", o.min_activity_agreement},
                               {"on_failure", o.drop_activity_failures ? "drop" : "keep_best"}};
    return s;
}

// A setting as a folder's synth.json recorded it. A realism lever added since the folder was made is absent from
// its record: absent reads as off (the model's default), so the folder stays valid while the new lever stays off.
json recorded_setting(const json& before, const std::string& key) {
    json recorded = before.value(key, json());
    if (key != "realism" || !recorded.is_object()) return recorded;
    return realism_record_as_today(recorded);
}

void check_or_write_settings(const std::string& out, const json& settings) {
    const std::string path = out + "/synth.json";
    if (fs::exists(path)) {
        const json before = read_json_file(path);
        for (const auto& [key, value] : settings.items()) {
            const json recorded = recorded_setting(before, key);
            if (recorded != value)
                throw Error(path, key,
                            value.dump() + " as this run asks (a folder holds one synthesis; use another --out)",
                            recorded.dump());
        }
        // A switch on then, off now (realism, capture_rate). The sensor model had an option of its own once, recorded
        // as "noise": none is what a folder without it means today.
        for (const auto& [key, value] : before.items())
            if (!settings.contains(key) && !(key == "noise" && value == "none"))
                throw Error(path, key,
                            "absent (off) as this run asks (a folder holds one synthesis; use another --out)",
                            value.dump());
        return;
    }
    write_file_atomic(path, settings.dump(1) + "\n");
}

}  // namespace

SampleOptions synth_sampling_defaults() {
    SampleOptions o;
    o.sampler = Sampler::dpmpp;
    o.steps = 50;
    return o;
}

SynthPlan plan_synth(const SynthOptions& o) {
    if (o.samples_per_prompt < 1)
        throw Error("synth", "--samples-per-prompt", "at least 1", std::to_string(o.samples_per_prompt));
    if (o.shards < 1 || o.shard < 0 || o.shard >= o.shards) throw Error("synth", "--shard", "I/N with 1 <= I <= N");
    if (o.max_retries < 0) throw Error("synth", "--retries", "0 or more", std::to_string(o.max_retries));
    if (!(o.min_activity_agreement >= 0 && o.min_activity_agreement <= 1))
        throw Error("synth", "--min-activity-agreement", "0 to 1", std::to_string(o.min_activity_agreement));
    if (o.out.empty()) throw Error("synth", "--out", "an output folder");
    o.sampling.validate();
    SynthPlan plan;
    plan.options = o;
    plan.frames = frames_for_seconds(o.seconds, "--seconds");
    plan.source = parse_motion_source(o.model);
    plan.imu.rate_hz = o.rate_hz;
    plan.imu.seed = o.sampling.seed;
    plan.imu.set_realism(parse_realism(o.realism));
    plan.imu.validate();
    plan.bodies = parse_body_specs(o.bodies);
    plan.sensors = parse_sensor_sets(o.sensors);
    plan.prompts = read_prompt_set(o.prompts, PromptActivity::required);
    return plan;
}

namespace {

// Rows for every recording of every marker (other shards' too); `source` is the model folder or retrieval:DATASET
// as given.
void write_manifest(const SynthOptions& o, const std::vector<JobMarker>& markers) {
    std::vector<ImuRecording> rows;
    for (const JobMarker& j : markers)
        for (const MarkerRecording& r : j.recordings) {
            ImuRecording row;
            row.path = r.path;
            row.dataset = "t2imu";
            row.subject = r.body;
            row.activity = j.activity;
            row.position = r.position;
            row.rate_hz = o.rate_hz;
            row.n_samples = r.n_samples;
            row.extra = {{"source", o.model},
                         {"prompt", j.prompt},
                         {"body", r.body},
                         {"seed", std::to_string(j.seed)},
                         {"job", j.job}};
            rows.push_back(std::move(row));
        }
    write_imu_manifest(o.out, rows, {"source", "prompt", "body", "seed", "job"});
}

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

SynthReport synth_report(const std::vector<JobMarker>& markers, int total_jobs, const SynthRunTiming& timing) {
    SynthReport r;
    std::map<std::string, std::vector<double>> scores;
    for (const JobMarker& j : markers) {
        ActivityCounts& a = r.per_activity[j.activity];
        (j.kept ? a.kept : a.dropped) += 1;
        if (j.activity_check) {  // what the last draw showed, kept or dropped
            a.shown[j.activity_check->shown] += 1;
            a.shows_activity_by_classifier = a.shows_activity_by_classifier.value_or(0) +
                                             shows_activity(j.activity_check->shown, canonical_activity(j.activity));
        }
        if (!j.source_draw.is_null())  // retrieval: whether the retrieved clip's tags name the activity
            a.shows_activity_by_tags =
                a.shows_activity_by_tags.value_or(0) + j.source_draw.value("tags_show_activity", false);
        const bool below = j.kept && j.activity_check && !j.activity_check->passed;
        a.kept_below_activity_agreement += below;
        r.motions_kept += j.kept;
        r.motions_kept_below_activity_agreement += below;
        r.jobs_regenerated += j.attempts.size() > 1;
        r.recordings += static_cast<int>(j.recordings.size());
        for (const MarkerAttempt& at : j.attempts)
            for (const std::string& f : at.failures) r.failed_attempts_by_score[f] += 1;
        for (const auto& [name, v] : j.quality) scores[name].push_back(v);
    }
    for (const auto& [name, v] : scores) r.quality_median[name] = median(v);
    r.jobs = total_jobs, r.jobs_done = static_cast<int>(markers.size()),
    r.motions_dropped = r.jobs_done - r.motions_kept;
    r.this_run = timing;
    return r;
}

// Per prompt, how the source's captions cover it (text/prompt_coverage.hpp), checked before any output; none for a
// source without captions.
std::vector<std::optional<MarkerCoverage>> check_coverage(const MotionSource& source, const SynthPlan& plan) {
    const std::vector<Prompt>& prompts = plan.prompts;
    const SynthOptions& o = plan.options;
    std::vector<std::optional<MarkerCoverage>> out(prompts.size());
    if (source.caption_index() == nullptr) return out;
    const std::vector<PromptCoverage> c =
        check_prompts_covered(*source.caption_index(), prompts, o.prompts, o.require_coverage);
    for (size_t i = 0; i < prompts.size(); ++i)
        out[i] =
            MarkerCoverage{c[i].covered(), c[i].summary(), c[i].nearest, c[i].similarity, c[i].attributes_uncovered};
    return out;
}

}  // namespace

SynthReport run_synth(const SynthPlan& plan) {
    const SynthOptions& o = plan.options;
    const std::vector<Prompt>& prompts = plan.prompts;
    const auto start = Clock::now();
    auto t0 = Clock::now();
    std::unique_ptr<MotionSource> source =
        open_motion_source(plan.source, o.sampling, o.device, o.vocab, o.activity_reference);
    std::optional<MotionActivityClassifier> classifier;
    if (!o.activity_reference.empty()) classifier = MotionActivityClassifier::load(o.activity_reference);
    const double load_s = since(t0);
    const json described = source->describe();
    const std::vector<std::optional<MarkerCoverage>> coverage = check_coverage(*source, plan);
    claim_output_folder(o.out);  // marked as t2imu's: a rerun resumes in it (core/output_path.hpp)
    make_directories(o.out + "/jobs", "jobs folder");
    check_or_write_settings(o.out, settings_json(plan, described));

    const int total = static_cast<int>(prompts.size()) * o.samples_per_prompt;
    const int first = static_cast<int>(static_cast<long long>(total) * o.shard / o.shards);
    const int last = static_cast<int>(static_cast<long long>(total) * (o.shard + 1) / o.shards);
    std::vector<bool> todo(static_cast<size_t>(last - first));
    for (int k = first; k < last; ++k) todo[static_cast<size_t>(k - first)] = !job_intact(o.out, k);
    const int jobs_to_run = static_cast<int>(std::count(todo.begin(), todo.end(), true));
    Progress progress("synth", static_cast<size_t>(jobs_to_run), "jobs");
    double generate_s = 0, score_s = 0, imu_s = 0;
    for (const std::vector<int>& jobs : job_groups(first, last, o.sampling.batch)) {
        if (std::none_of(jobs.begin(), jobs.end(), [&](int k) { return todo[static_cast<size_t>(k - first)]; }))
            continue;
        std::vector<std::string> texts, labels, expected;
        for (int k : jobs) {
            const Prompt& prompt = prompts[static_cast<size_t>(k / o.samples_per_prompt)];
            texts.push_back(prompt.text);
            labels.push_back(prompt.activity);
            expected.push_back(classifier ? reference_activity(prompt.activity, classifier->classes()) : "");
        }
        const std::vector<Drawn> drawn = draw_filtered(
            *source, jobs, texts, labels, expected, classifier ? &*classifier : nullptr, plan, &generate_s, &score_s);
        t0 = Clock::now();
        parallel_for(jobs.size(), o.threads, [&](size_t i) {
            const int k = jobs[i];
            if (!todo[static_cast<size_t>(k - first)]) return;  // done before the interruption, with these very bytes
            const size_t p = static_cast<size_t>(k / o.samples_per_prompt);
            write_job(plan, k, prompts[p], coverage[p], k % o.samples_per_prompt, drawn[i]);
            progress.advance();
        });
        imu_s += since(t0);
    }
    progress.finish();
    t0 = Clock::now();
    const std::vector<JobMarker> markers = read_job_markers(o.out);
    write_manifest(o, markers);
    SynthReport report =
        synth_report(markers, total,
                     {jobs_to_run, o.threads, load_s, generate_s, score_s, imu_s, since(t0), since(start), o.device});
    report.realism =
        plan.imu.realism().to_json();  // the model in effect; each recording's draws are in its job's marker
    write_synth_report(o.out, report);
    return report;
}

}  // namespace t2imu
