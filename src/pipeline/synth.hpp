// The main job: prompts -> motions -> bodies -> virtual sensors -> an IMU dataset (imu/imu_dataset.hpp's
// layout) with the motions that made it.
//
// Work is cut into jobs, one per prompt and sample (job k = prompt k / S, sample k % S for S samples per prompt),
// each drawn from its own seed, so a job's output does not depend on which other jobs run, on the batch size
// or on the shard beyond float rounding (jobs sampled in differently composed batches agree to ~1e-4 m/s^2).
// Batches are fixed groups of job indices, drawn whole whenever one of their jobs is left to do, so the same
// settings give the same bytes: run twice, or interrupted (even by kill -9) and resumed. Output folder:
//   synth.json                      the settings; a resume or a second shard refuses a folder made with others
//   jobs/<job>.json                 written last for a job: it is done (resume skips it); its prompt, seeds,
//                                   quality scores, and its recordings or why it was dropped
//   recordings/<job>/<body>/<position>.csv   t,acc_xyz,gyr_xyz (s, m/s^2 with gravity, rad/s)
//   motions/<job>_joints.npy, <job>.bvh   the motion: SMPL-22 joints [F,22,3] (20 fps; metres, Y up); the
//                                   sensors' copy at the capture rate (capture_rate) is not written: the marker
//                                   names its rate (sensor_motion_fps) and the retrieved clip
//   manifest.csv                    rebuilt from every job marker when a run ends: dataset t2imu, subject = the
//                                   body (a synthetic subject), extra columns source, prompt, body, seed, job
//   synth_report.json               counts per activity, the quality filter's work and the time of each stage
// Shards: --shard I/N takes the I-th of N contiguous blocks of jobs. Shards written to one folder (or copied
// together) are merged by running once more without --shard: every job is done, the manifest is rebuilt.
//
// Each drawn motion is first placed on the floor (motion/motion_quality.hpp: place_on_floor), as captured clips are.
// Quality filter (motion/motion_quality.hpp, and the activity check below): a motion over any threshold is drawn again
// with the next seed, up to max_retries times; one still failing then is dropped (recorded in its marker and the
// report), except that one failing only the activity check keeps its best-agreeing draw (see SynthOptions). Seeds:
// attempt a of job k draws from seed + k + a * kSeedStridePerAttempt.
#pragma once
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "diffusion/sample_options.hpp"
#include "imu/synth_folder.hpp"
#include "imu/virtual_imu.hpp"
#include "motion/motion_quality.hpp"
#include "pipeline/motion_source_spec.hpp"
#include "text/prompt_set.hpp"

namespace t2imu {

constexpr uint64_t kSeedStridePerAttempt = 1000003;

// The sampling of t2imu synth and of the experiments: DPM-Solver++ 2M, 50 denoiser calls. Fewer steps smooth the
// learned default's motions and cost HAR
// (docs/results.md on sampler steps;
// bench/README.md#samplers-quality-against-steps).
SampleOptions synth_sampling_defaults();

struct SynthOptions {
    std::string prompts;  // prompt set file (text/prompt_set.hpp)
    int samples_per_prompt = 1;
    std::string model = "models/default";                // a model folder, retrieval:DATASET or hybrid:...
    std::string vocab;                                   // GloVe vocabulary for retrieval ("" = default)
    SampleOptions sampling = synth_sampling_defaults();  // sampler, steps, guidance, seed (of job 0), batch
    double seconds = 6;                                  // motion length (20 fps; at most 9.8 s)
    std::string bodies = "paper8", sensors = "realworld";
    std::string realism = "none";  // imu/realism.hpp: a preset or a .toml file
    double rate_hz = 50;
    // The virtual sensors see a retrieved captured clip at its capture rate (MotionSource::capture_rate_motion)
    // rather than at 20 fps; motions without a capture-rate copy (derived clips, the models') stay at 20 fps. On by
    // default: on the shared SisFall subjects it brought the waist signals' texture nearer the real ones and cost
    // nothing (docs/realism.md on the capture rate at the sensors).
    bool capture_rate = true;
    bool filter = true;
    // Learned descents pass the support ground in a minority of draws (their feet do not always plant), so a prompt
    // gets several; docs/results.md ("The main job's retries") measured the count.
    int max_retries = 9;
    MotionQualityThresholds thresholds = default_quality_thresholds();
    // Activity check (motion/motion_activity.hpp): with a reference CSV, a motion whose agreement with its
    // prompt's activity is below min_activity_agreement fails like a quality score ("activity"). 0.55 is the
    // 0.5th percentile of the captured clips' agreement with their own activity, leave-one-subject-out, so as
    // for the other thresholds a failing motion is less typical of its activity than 199 in 200 captured ones.
    // Prompts whose activity the reference lacks are not checked. A job whose every draw fails the activity
    // check and nothing else keeps its best-agreeing draw (marker: activity_check.passed false) unless
    // drop_activity_failures: dropping starves exactly the activities the model renders worst.
    std::string activity_reference;  // "" = no activity check
    double min_activity_agreement = 0.55;
    bool drop_activity_failures = false;
    // A prompt the source's training captions do not cover (text/prompt_coverage.hpp: an activity without
    // captions, an attribute none of its captions names) is an error instead of a warning.
    bool require_coverage = false;
    int shard = 0, shards = 1;  // this run does shard `shard` (0-based) of `shards`
    std::string device = "cpu";
    int threads = 1;  // workers for the bodies/IMU stage
    std::string out;
};

// The job as typed values, made at the door by plan_synth: each spelling (the source, the prompt set, the bodies, the
// sensors, the realism model and its sensor model) parsed once, every value checked, before
// any work. What runs after reads these; the options' spellings stay for the record (synth.json, the manifest).
struct SynthPlan {
    SynthOptions options;
    MotionSourceSpec source;
    std::vector<Prompt> prompts;
    std::vector<BodySpec> bodies;
    std::vector<SensorPlacement> sensors;
    VirtualImuOptions imu;  // rate, seed (of job 0), the realism model and its sensor model
    int frames = 0;         // motion length at 20 fps
};

// Throws Error naming the option (or the file and field) for a value out of range, not finite, unknown or unreadable,
// so a bad value never leaves a half-made folder.
SynthPlan plan_synth(const SynthOptions& options);

// Runs (or resumes) the jobs of this shard, then rebuilds the manifest and the report from every marker in the
// folder. Returns the report (synth_report.json). Progress over this run's jobs: core/progress.hpp.
SynthReport run_synth(const SynthPlan& plan);

}  // namespace t2imu
