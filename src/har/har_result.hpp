// The result of `t2imu har run` and of the experiment's HAR trainings: its type, its JSON (RESULT.json) and the
// reader. Torch-free, so the report and the experiment summary read it typed; har/nn writes it.
#pragma once
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "har/har_metrics.hpp"

namespace t2imu {

struct HarRun {
    double balanced_accuracy = 0, macro_f1 = 0;
    int epochs = 0;  // of the last stage (the fine-tuning under the finetune protocol)
    double seconds_per_epoch = 0;
    Confusion confusion;
    // Training on several sets (har/nn/har_training.hpp): the subjects drawn from the set that is also the test set and
    // the subjects tested (empty without a draw), and the training windows each set gave, in training_sets' order.
    std::vector<std::string> train_subjects, test_subjects;
    std::vector<size_t> set_windows;
};

struct HarResult {
    std::vector<std::string> classes;
    std::vector<HarRun> runs;
    std::vector<std::string> run_names;          // "seed 3", "draw 2" or the held-out subject
    size_t train_windows = 0, test_windows = 0;  // per run; summed over runs where each run has its own split
    // Several training sets: their names (dataset folders) in order, each one's share of a batch (SeveralSetsOptions),
    // and the protocol ("mix" or "finetune"; "" for one set).
    std::vector<std::string> training_sets;
    std::vector<double> shares;
    std::string protocol;
    int finetune_epochs = 0;
    double finetune_learning_rate = 0;
};

// The runs' confusion matrices summed (rows = true class).
Confusion summed_confusion(const HarResult& r);

// One score over a result's runs: mean, sample sd (n - 1; 0 for one run) and the runs themselves.
struct ScoreSummary {
    double mean = 0, sd = 0;
    std::vector<double> runs;
};
ScoreSummary score_summary(const HarResult& r, double HarRun::*score);
nlohmann::json score_summary_json(const ScoreSummary& s);  // {mean, sd, runs}

// RESULT.json: classes, balanced_accuracy {mean, sd, runs}, macro_f1 {...}, per_class_recall (mean over runs),
// confusion (summed over runs, rows = true class), plus counts and timings, and `run_records`: each run's name,
// scores, epochs, its own confusion and (training on several sets) its subjects and windows per set, so results of
// separate runs can be read back and merged.
std::string har_result_json(const HarResult& r, const std::string& description);
// The HarResult a har_result_json document holds; throws Error naming `path` and the key when it has none.
HarResult read_har_result(const std::string& path);
HarResult parse_har_result(const nlohmann::json& doc, const std::string& path);
// True when `doc` looks like a har_result_json document (how the report finds results by content).
bool is_har_result(const nlohmann::json& doc);
// The runs of several results over the same classes and training sets, in order (e.g. one file per seed). Window
// counts must agree unless the runs carry their own subject draws; then they are summed.
HarResult merge_har_results(const std::vector<HarResult>& parts);

}  // namespace t2imu
