// The paper's experiment (Häusler et al.) on the data we hold, as one resumable run:
//
//   for every motion source (a model folder, or the retrieval baseline) and every real data set:
//     t2imu synth on that data set's prompt set and sensor placement        -> synth/<source>-<set>/
//     catch22 of every real and synthetic window                            -> features/{real,<source>}-<set>.csv
//     real vs synthetic: classifier two-sample test, per-feature distances  -> gap/<source>-<set>.json
//     level and texture statistics per activity, real beside synthetic,
//     at each of the set's positions (analysis/signal_statistics.hpp)       ->
//     signal-stats/<source>-<set>-<position>.json DeepConvLSTM trained only on the synthetic set, tested on the real
//     one, one training per seed (har.repeats of them)                           -> runs/<source>-<set>/seed-<k>.jsonl
//                                                                              merged: har/<source>-<set>.json
//   per real set: t-SNE of real and every source's windows (a seeded draw of
//     at most features.tsne_points windows per group)                      -> tsne/<set>.csv
//   per real set: the real-to-real leave-subjects-out ceiling on the classes
//     the synthetic sets share with it                                     -> har/ceiling-<set>.json
//   L_acc of two models on the same clips and draws, per activity category -> lacc/<model>.csv, lacc/change.csv
//   the table of it all                                                     -> summary.json, summary.md
//   the HTML report                                                         -> report/index.html
//
// Every output is written atomically and a step whose output exists is skipped, so a killed run continues where
// it stopped and raising har.repeats later trains only the new seeds. Order: everything cheap first (synthesis,
// features, t-SNE, L_acc), then the HAR trainings seed by seed across all rows, rewriting the summary and report
// after each round, so a partial run already shows every row. The synthetic sets carry their own settings
// check (pipeline/synth.hpp): running with other synthesis settings into the same folder is refused.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/tsne.hpp"
#include "har/low_data_curve.hpp"
#include "har/nn/har_training.hpp"
#include "har/windowing.hpp"
#include "pipeline/synth.hpp"

namespace t2imu {

struct ExperimentSource {
    std::string name;   // row name in tables and file names
    std::string model;  // model folder or retrieval:DATASET (as t2imu synth --model)
};

struct ExperimentRealSet {
    std::string name;                    // column name in tables and file names
    std::string dataset;                 // IMU dataset folder (imu/imu_dataset.hpp layout)
    std::string prompts;                 // prompt set in this data set's class names
    std::string sensors;                 // placement set the synthetic recordings are made at
    std::vector<std::string> positions;  // positions compared (windowing.hpp names)
    int ceiling_folds = 0;  // real-to-real ceiling: subjects dealt into this many folds (0: one per subject; -1: none)
    std::string realism;    // realism model of this set's synthetic recordings ("" = [synth]'s realism)
};

struct ExperimentLacc {
    std::string before, after;  // source names (model folders); empty: the step is skipped
    std::string dataset, split = "test", vocab;
    uint64_t seed = 0;
    double tau = 0.45;  // the paper's similarity threshold for the category Other
};

// [low_data]: the low-data curve (pipeline/experiment_low_data.cpp). Per real set, for each K real training subjects
// (drawn `draws` times, seeds har.seed + draw, tested on that set's other subjects): real only, and each source's
// synthetic set with each protocol (har/nn/har_training.hpp) -> low-data/<arm>/<protocol>-k<K>.json, the curves in
// low-data/curves.json and low-data/summary.md. K = 0 is the experiment's synthetic-only row.
struct ExperimentLowData {
    std::vector<int> train_subjects;  // K; kAllSubjects: every subject but all_test_subjects. Empty: no curve
    static constexpr int kAllSubjects = -1;
    int all_test_subjects = 4;  // at K = all, drawn per draw
    int draws = 5;
    std::vector<HarProtocol> protocols = {HarProtocol::mix, HarProtocol::finetune};
    double synthetic_share = 0.5;  // mix: the synthetic set's share of each batch (0: in proportion to windows)
    int finetune_epochs = 20;
    double finetune_learning_rate = 3e-4;
    double finetune_synthetic_share = 0;  // finetune: the synthetic set's share of each fine-tuning batch (0: none)
};

struct ExperimentConfig {
    std::string path;    // the TOML it was read from (errors name it); "" for one made in code
    SynthOptions synth;  // shared synthesis settings; prompts, model, sensors and out are set per row
    std::vector<ExperimentSource> sources;
    std::vector<ExperimentRealSet> real_sets;
    WindowOptions windows;  // rate, length, overlap, channels; positions are set per real set
    HarOptions har;         // repeats = trainings per row, with seeds har.seed + k
    int tsne_points = 1500;
    TsneOptions tsne;
    uint64_t feature_seed = 0;  // the two-sample test's folds and the t-SNE draw
    ExperimentLacc lacc;
    ExperimentLowData low_data;
};

// Reads experiments/*.toml (see experiments/paper.toml for every key); unknown keys are refused.
ExperimentConfig read_experiment_config(const std::string& path);

// [low_data] of an experiment TOML (the section `low_data`), every value checked; Error names `path` and the key.
class TomlSection;
ExperimentLowData read_experiment_low_data(TomlSection section, const std::string& path);

// The low-data curves of every real set, each step skipped when its file exists; `windows` gives a dataset folder's
// windows for a real set (read once by the experiment). Writes low-data/curves.json and low-data/summary.md.
std::vector<LowDataCurve> run_low_data(
    const ExperimentConfig& config, const std::string& out,
    const std::function<const WindowSet&(const std::string&, const ExperimentRealSet&)>& windows,
    const std::function<void(const std::string&)>& log);
// low-data/summary.md: per real set, balanced accuracy per K and arm (mean ± sd over the draws, each draw), and the
// best synthetic arm's gain over real only.
std::string low_data_markdown(const std::vector<LowDataCurve>& curves);

// summary.json: the experiment folder's table, made from its har/, gap/ and lacc/ files (each read through its
// own reader: read_har_result, two_sample_balanced_accuracy, read_lacc_csv).
struct ExperimentRow {
    std::string source, model, real_set;
    std::vector<std::string> classes;  // those the HAR trainings scored
    double chance = 0;                 // 1 / classes
    ScoreSummary balanced_accuracy, macro_f1;
    size_t train_windows = 0, test_windows = 0;
    double two_sample_balanced_accuracy = 0;
};

struct ExperimentCeiling {
    std::string real_set, description;
    std::vector<std::string> classes;
    ScoreSummary balanced_accuracy;
};

struct LaccGroupChange {
    double samples = 0, change_percent = 0;
};

struct ExperimentSummary {
    int har_repeats = 0, har_rounds_done = 0;
    std::vector<ExperimentRow> rows;          // per source and real set, real sets in config order
    std::vector<ExperimentCeiling> ceilings;  // per real set that has one
    std::string lacc_before, lacc_after;      // empty: no L_acc step
    std::map<std::string, LaccGroupChange> lacc_groups;
};

nlohmann::json experiment_summary_json(const ExperimentSummary& s);

// A row's name in tables and file names: "<source>-<set>".
std::string experiment_row_name(const ExperimentSource& source, const ExperimentRealSet& set);

// One synthetic-to-real comparison: a source's synthetic version of a real data set.
struct ExperimentRowPlan {
    size_t source = 0, set = 0;  // into the config's sources and real_sets
    SynthPlan synth;             // [synth] with the set's prompts, sensors and realism; out: <out>/synth/<source>-<set>
};

// The experiment as typed values, made at the door by plan_experiment: every row's synthesis planned (plan_synth:
// its prompts read, its realism and sensor models parsed once, every value checked), so a bad row is refused before
// the first synthesis starts rather than after the rows before it.
struct ExperimentPlan {
    ExperimentConfig config;
    std::string out;
    std::vector<ExperimentRowPlan> rows;  // real sets in config order, the sources within each
};

// Throws Error naming the config file, the row and what t2imu synth refuses in it.
ExperimentPlan plan_experiment(const ExperimentConfig& config, const std::string& out);

// Runs or resumes the experiment into plan.out; `log` receives one line per step done. Returns summary.json's table.
ExperimentSummary run_experiment(const ExperimentPlan& plan, const std::function<void(const std::string&)>& log = {});

// summary.md: balanced accuracy per source and real set (mean ± sd over the runs, with the paper's figures
// beside them), the real-to-real ceilings, chance, the two-sample test and the L_acc change.
std::string experiment_summary_markdown(const ExperimentSummary& summary);

}  // namespace t2imu
