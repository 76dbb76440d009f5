// A synthesis folder: what `t2imu synth --out DIR` writes, and the one schema its writer (pipeline/synth.cpp) and
// every reader (resume, the manifest, the report, the activity confusion, the experiment) go through. It sits in
// imu/, below both the writer (pipeline/) and the readers (report/), and is torch-free.
//
//   DIR/synth.json                          the settings; a resume must ask for the same (pipeline/synth.cpp)
//   DIR/jobs/<job>.json                     a JobMarker per finished job, written last: the job is done
//   DIR/motions/<job>_joints.npy, .bvh      a kept job's motion ([F,22,3] metres, Y up, 20 fps; BVH)
//   DIR/recordings/<job>/<body>/<pos>.csv   its virtual IMU recordings; DIR/manifest.csv lists them
//                                           (imu/imu_dataset.hpp)
//   DIR/synth_report.json                   a SynthReport: what the folder holds and the last run's time
//
// Markers and reports from before a field existed still read: index, sample and frames read as -1, a
// recording's bytes as -1 (any size), its tempo as 1 and its tilt as 0.
#pragma once
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace t2imu {

struct MarkerAttempt {
    uint64_t seed = 0;
    std::vector<std::string> failures;  // names of the quality scores (and "activity") it failed
    std::optional<double> activity_agreement;
};

struct MarkerRecording {
    std::string path, body, position;  // path relative to the folder
    uint64_t n_samples = 0;
    int64_t bytes = -1;         // the file's size as written; -1: not recorded
    double tempo = 1;           // the realism model's draws for this recording (imu/realism.hpp): time warp and
    double mount_tilt_deg = 0;  // mounting tilt (recorded under the tilt lever's key)
};

struct MarkerFile {
    std::string path;  // relative to the folder
    int64_t bytes = 0;
};

struct ActivityCheck {
    std::string shown;  // the activity the motion shows (motion/motion_activity.hpp)
    double agreement = 0;
    bool passed = false;
};

// How well the motion source's training captions cover the job's prompt (text/prompt_coverage.hpp).
struct MarkerCoverage {
    bool covered = true;
    std::string summary;                 // "covered", or what is not ("activity 'ironing' has no training captions")
    std::vector<std::string> nearest;    // the nearest training captions of its activity
    std::vector<double> similarity;      // their SIF cosine
    std::vector<std::string> uncovered;  // attributes asked that no caption of the activity names
};

struct JobMarker {
    std::string job;  // "j00003"
    int index = -1, sample = -1, frames = -1;
    std::string prompt, activity;
    uint64_t seed = 0;  // of the kept (or last) draw
    std::vector<MarkerAttempt> attempts;
    std::map<std::string, double> quality;  // the kept draw's quality scores (motion/quality.hpp)
    bool kept = false;
    std::vector<MarkerRecording> recordings;
    std::optional<std::vector<MarkerFile>> motions;  // a kept job's motion files
    std::optional<double> sensor_motion_fps;         // when the sensors saw another copy (the capture rate)
    std::optional<ActivityCheck> activity_check;
    nlohmann::json source_draw;              // the source's own record of the draw (retrieval: the clip), or null
    std::optional<MarkerCoverage> coverage;  // absent for a source without training captions
};

// A job's name ("j00003" for job 3) and its files relative to the folder: the one place they are spelled.
std::string job_name(int index);
std::string job_joints_file(const std::string& job);     // motions/<job>_joints.npy
std::string job_bvh_file(const std::string& job);        // motions/<job>.bvh
std::string job_recordings_dir(const std::string& job);  // recordings/<job>

nlohmann::json job_marker_json(const JobMarker& m);
// Error naming `path` and the dotted key ("recordings.3.n_samples") when a field is missing or mistyped.
JobMarker parse_job_marker(const nlohmann::json& doc, const std::string& path);
std::string job_marker_path(const std::string& dir, const std::string& job);
void write_job_marker(const std::string& dir, const JobMarker& m);  // atomically
JobMarker read_job_marker(const std::string& path);
// Every jobs/*.json of `dir`, in job order (none when there is no jobs/ folder).
std::vector<JobMarker> read_job_markers(const std::string& dir);

struct ActivityCounts {
    int kept = 0, kept_below_activity_agreement = 0, dropped = 0;
    std::map<std::string, int> shown;                 // what the last draws showed (with an activity check)
    std::optional<int> shows_activity_by_classifier;  // with an activity check
    std::optional<int> shows_activity_by_tags;        // retrieval: clips whose tags name the activity
};

struct SynthRunTiming {
    int jobs_run = 0, threads = 1;
    double load_s = 0, motion_generation_s = 0, quality_scoring_s = 0, bodies_imu_write_s = 0, manifest_s = 0,
           total_s = 0;
    std::string device;
};

struct SynthReport {
    int jobs = 0, jobs_done = 0, motions_kept = 0, motions_dropped = 0, motions_kept_below_activity_agreement = 0;
    int jobs_regenerated = 0, recordings = 0;
    std::map<std::string, ActivityCounts> per_activity;
    std::map<std::string, int> failed_attempts_by_score;
    std::map<std::string, double> quality_median;
    SynthRunTiming this_run;
    nlohmann::json realism;  // the realism model in effect (imu/realism.hpp's JSON record)
};

nlohmann::json synth_report_json(const SynthReport& r);
SynthReport parse_synth_report(const nlohmann::json& doc, const std::string& path);
void write_synth_report(const std::string& dir, const SynthReport& r);  // atomically
SynthReport read_synth_report(const std::string& dir);

}  // namespace t2imu
