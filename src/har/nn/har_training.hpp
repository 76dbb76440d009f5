// Train DeepConvLSTM on one set of windows and test it on another: the paper's synthetic-to-real experiment
// (and leave-one-subject-out real-to-real as its ceiling). Torch stays inside the .cpp.
//
// Training: per-channel normalisation fitted on the training windows only; 0.15 of the training trials
// (whole trials, stratified by class, so windows of one trial never sit on both sides) held out for early
// stopping on balanced accuracy (patience 5 epochs, at most `max_epochs`); class-weighted cross-entropy
// (weights inverse to class frequency) so a rare class counts as much as a frequent one; Adam, learning rate
// 1e-3, batch 64. Adam rather than the paper's RMSProp: the same per-parameter step scaling plus momentum,
// and the default of HAR re-implementations; the choice changes results by less than run-to-run variation.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "har/har_metrics.hpp"
#include "har/windowing.hpp"

namespace t2imu {

struct HarOptions {
    int repeats = 10;
    uint64_t seed = 0;
    int max_epochs = 40, patience = 5, batch = 64;
    double learning_rate = 1e-3, validation_share = 0.15;
    bool verbose = false;

    // Throws Error naming the option (--repeats, --epochs...) for a value out of range; the trainings call it.
    void validate() const;
};

struct HarRun {
    double balanced_accuracy = 0, macro_f1 = 0;
    int epochs = 0;
    double seconds_per_epoch = 0;
    Confusion confusion;
};

struct HarResult {
    std::vector<std::string> classes;
    std::vector<HarRun> runs;
    std::vector<std::string> run_names;  // "seed 3" or the held-out subject
    size_t train_windows = 0, test_windows = 0;
};

// The classes both sets share (class_map.hpp rules), then `repeats` trainings with seeds seed, seed+1, ...
HarResult train_and_test(const WindowSet& train, const WindowSet& test, const HarOptions& options);
// One fold per subject: train on the others, test on that subject (each fold trained once). With folds > 0,
// subjects are dealt (sorted by name, round robin) into that many folds instead: leave-k-subjects-out, for
// data sets with many subjects where one training per subject costs too much.
HarResult leave_one_subject_out(const WindowSet& data, const HarOptions& options, int folds = 0);

// One score over a result's runs: mean, sample sd (n - 1; 0 for one run) and the runs themselves.
struct ScoreSummary {
    double mean = 0, sd = 0;
    std::vector<double> runs;
};
ScoreSummary score_summary(const HarResult& r, double HarRun::*score);
nlohmann::json score_summary_json(const ScoreSummary& s);  // {mean, sd, runs}

// RESULT.json: classes, balanced_accuracy {mean, sd, runs}, macro_f1 {...}, per_class_recall (mean over runs),
// confusion (summed over runs, rows = true class), plus counts and timings, and `run_records`: each run's name,
// scores, epochs and its own confusion, so results of separate runs can be read back and merged.
std::string har_result_json(const HarResult& r, const std::string& description);
// The HarResult a har_result_json document holds (its run_records); throws Error naming `path` when it has none.
HarResult read_har_result(const std::string& path);
// The runs of several results over the same classes and data, in order (e.g. one file per seed).
HarResult merge_har_results(const std::vector<HarResult>& parts);

}  // namespace t2imu
