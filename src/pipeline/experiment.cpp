#include "pipeline/experiment.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <set>

#include "analysis/activity_categories.hpp"
#include "analysis/catch22_table.hpp"
#include "analysis/domain_gap.hpp"
#include "analysis/lacc_analysis.hpp"
#include "analysis/signal_statistics.hpp"
#include "analysis/tsne_table.hpp"
#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/json_file.hpp"
#include "core/output_path.hpp"
#include "diffusion/lacc_evaluation.hpp"
#include "diffusion/text_to_motion.hpp"
#include "imu/imu_dataset.hpp"
#include "report/html_report.hpp"
#include "text/sentence_similarity.hpp"
#include "text/word_vectors.hpp"

namespace t2imu {

namespace fs = std::filesystem;

namespace {

// One row of the plan, its source and set looked up.
struct Row {
    const ExperimentSource* source;
    const ExperimentRealSet* set;
    const SynthPlan* synth;
    std::string id() const { return experiment_row_name(*source, *set); }
};

class Experiment {
public:
    Experiment(const ExperimentPlan& plan, const std::function<void(const std::string&)>& log)
        : c_(plan.config), out_(plan.out), log_(log) {
        for (const ExperimentRowPlan& r : plan.rows)
            rows_.push_back({&c_.sources[r.source], &c_.real_sets[r.set], &r.synth});
    }

    ExperimentSummary run() {
        for (const Row& r : rows_) synthesise(r);
        for (const ExperimentRealSet& set : c_.real_sets) {
            features(path("features/real-" + set.name + ".csv"), set.dataset, set);
            for (const Row& r : rows_)
                if (r.set == &set) {
                    features(path("features/" + r.id() + ".csv"), path("synth/" + r.id()), set);
                    domain_gap_of(r);
                    signal_statistics_of(r);
                }
            tsne_of(set);
        }
        lacc();
        ExperimentSummary summary;
        for (int k = 0; k < c_.har.repeats; ++k) {
            for (const Row& r : rows_) har_run(r, k);
            if (k == 0)
                for (const ExperimentRealSet& set : c_.real_sets) ceiling(set);
            summary = summarise(k + 1);
            write_file_atomic(path("summary.json"), experiment_summary_json(summary).dump(2) + "\n");
            write_file_atomic(path("summary.md"), experiment_summary_markdown(summary));
            write_report(out_, path("report"));
            say("round " + std::to_string(k + 1) + "/" + std::to_string(c_.har.repeats) +
                " of HAR trainings done: " + path("summary.md"));
        }
        if (!c_.low_data.train_subjects.empty()) {
            run_low_data(
                c_, out_,
                [this](const std::string& dataset, const ExperimentRealSet& set) -> const WindowSet& {
                    return windows(dataset, set);
                },
                log_);
            write_report(out_, path("report"));
            say("low-data curves done: " + path("low-data/summary.md"));
        }
        return summary;
    }

private:
    std::string path(const std::string& relative) const { return (fs::path(out_) / relative).string(); }
    void say(const std::string& line) const {
        if (log_) log_(line);
    }

    WindowOptions windows_for(const ExperimentRealSet& set) const {
        WindowOptions w = c_.windows;
        w.positions = set.positions;
        return w;
    }

    // Windows of a dataset folder, read once per run (the HAR rounds reuse them).
    const WindowSet& windows(const std::string& dataset, const ExperimentRealSet& set) {
        auto it = windows_.find(dataset);
        if (it == windows_.end())
            it = windows_.emplace(dataset, make_windows(read_imu_dataset(dataset), windows_for(set))).first;
        return it->second;
    }

    void synthesise(const Row& r) {
        const SynthReport report = run_synth(*r.synth);
        say("synth " + r.id() + ": " + std::to_string(report.motions_kept) + " motions kept, " +
            std::to_string(report.recordings) + " recordings");
    }

    void features(const std::string& file, const std::string& dataset, const ExperimentRealSet& set) {
        if (fs::exists(file)) return;
        const WindowSet& w = windows(dataset, set);
        write_csv(file, catch22_window_table(w, window_channel_names(windows_for(set)), false, c_.synth.threads));
        say("catch22 of " + std::to_string(w.size()) + " windows: " + file);
    }

    void domain_gap_of(const Row& r) {
        const std::string file = path("gap/" + r.id() + ".json");
        if (fs::exists(file)) return;
        const DomainGap gap = domain_gap(read_csv(path("features/real-" + r.set->name + ".csv")),
                                         read_csv(path("features/" + r.id() + ".csv")), c_.feature_seed);
        write_file_atomic(file, domain_gap_json(gap).dump(2) + "\n");
        say("two-sample test " + r.id() + ": balanced accuracy " + std::to_string(gap.overall.balanced_accuracy));
    }

    // A real data set's recordings, read once per run (every source's row and every variant of an ablation compares
    // with them).
    const std::vector<ImuRecording>& real_recordings(const std::string& dataset) {
        auto it = real_recordings_.find(dataset);
        if (it == real_recordings_.end()) it = real_recordings_.emplace(dataset, read_imu_dataset(dataset)).first;
        return it->second;
    }

    // The level and texture statistics of each position, synthetic beside real, per activity (HAR's rate).
    void signal_statistics_of(const Row& r) {
        for (const std::string& position : r.set->positions) {
            const std::string file = path("signal-stats/" + r.id() + "-" + position + ".json");
            if (fs::exists(file)) continue;
            SignalStatisticsOptions o;
            o.position = position;
            o.rate_hz = c_.windows.rate_hz;
            const SignalStatisticsComparison stats = compare_signal_statistics(
                real_recordings(r.set->dataset), read_imu_dataset(path("synth/" + r.id())), o);
            write_file_atomic(file, signal_statistics_comparison_json(stats).dump(2) + "\n");
            say("signal statistics " + r.id() + " at " + position + ": " + file);
        }
    }

    // At most tsne_points windows per group (real, then each source in config order), drawn with a seeded shuffle.
    void tsne_of(const ExperimentRealSet& set) {
        const std::string file = path("tsne/" + set.name + ".csv");
        if (fs::exists(file)) return;
        CsvTable all;
        std::mt19937_64 rng(c_.feature_seed);
        const auto add = [&](const std::string& group, const std::string& features_file) {
            const CsvTable t = read_csv(features_file);
            if (all.header.empty()) {
                all.header = {"source"};
                all.header.insert(all.header.end(), t.header.begin(), t.header.end());
            } else if (!std::equal(t.header.begin(), t.header.end(), all.header.begin() + 1) ||
                       t.header.size() + 1 != all.header.size()) {
                throw Error(features_file, "header", "the columns of the other feature tables of " + set.name);
            }
            std::vector<size_t> order(t.rows.size());
            std::iota(order.begin(), order.end(), 0);
            std::shuffle(order.begin(), order.end(), rng);
            order.resize(std::min(order.size(), static_cast<size_t>(c_.tsne_points)));
            std::sort(order.begin(), order.end());
            for (size_t i : order) {
                std::vector<std::string> row = {group};
                row.insert(row.end(), t.rows[i].begin(), t.rows[i].end());
                all.rows.push_back(row);
            }
        };
        add("real", path("features/real-" + set.name + ".csv"));
        for (const Row& r : rows_)
            if (r.set == &set) add(r.source->name, path("features/" + r.id() + ".csv"));
        TsneOptions o = c_.tsne;
        // scikit-learn refuses perplexity >= N; the affinity search needs about 3 x perplexity neighbours.
        o.perplexity = std::min(o.perplexity, std::max(1.0, (static_cast<double>(all.rows.size()) - 1) / 3.0 - 1));
        std::set<std::string> labels(kWindowLabelColumns.begin(), kWindowLabelColumns.end());
        labels.insert("source");
        const TsneTable t = tsne_table(all, labels, o, file);
        write_csv(file, t.embedding);
        say("t-SNE of " + std::to_string(all.rows.size()) + " windows: " + file);
    }

    const ExperimentSource& source(const std::string& name) const {
        for (const ExperimentSource& s : c_.sources)
            if (s.name == name) return s;
        throw Error("experiment", "source", "a [[source]] named " + name);
    }

    void lacc() {
        const ExperimentLacc& l = c_.lacc;
        if (l.before.empty()) return;
        for (const std::string& name : {l.before, l.after}) {
            const std::string file = path("lacc/" + name + ".csv");
            if (fs::exists(file)) continue;
            std::unique_ptr<MotionModel> model = load_motion_model(source(name).model, c_.synth.device);
            write_csv(file, evaluate_lacc(*model, l.dataset, l.split, l.seed));
            say("L_acc of " + name + " on " + l.dataset + " (" + l.split + "): " + file);
        }
        const std::string change = path("lacc/change.csv");
        if (fs::exists(change)) return;
        const WordVectors vectors = WordVectors::load(l.vocab);
        const SifEncoder sif(vectors, kCategorySifWeight);
        const LaccAnalysis a =
            analyse_lacc(read_lacc_csv(path("lacc/" + l.before + ".csv")),
                         read_lacc_csv(path("lacc/" + l.after + ".csv")), ActivityCategorizer(sif, l.tau));
        write_file_atomic(change, lacc_analysis_csv(a));
        say("L_acc change " + std::to_string(a.all.change_percent()) + " %: " + change);
    }

    HarOptions one_training(uint64_t seed) const {
        HarOptions o = c_.har;
        o.repeats = 1;
        o.seed = seed;
        return o;
    }

    void har_run(const Row& r, int k) {
        const std::string file =
            path("runs/" + r.id() + "/seed-" + std::to_string(c_.har.seed + static_cast<uint64_t>(k)) + ".jsonl");
        if (!fs::exists(file)) {
            const HarResult result =
                train_and_test(windows(path("synth/" + r.id()), *r.set), windows(r.set->dataset, *r.set),
                               one_training(c_.har.seed + static_cast<uint64_t>(k)));
            write_file_atomic(file, nlohmann::json::parse(har_result_json(result, "")).dump() + "\n");
            say("HAR " + r.id() + " seed " + std::to_string(c_.har.seed + static_cast<uint64_t>(k)) +
                ": balanced accuracy " + std::to_string(result.runs[0].balanced_accuracy));
        }
        std::vector<HarResult> parts;
        for (int j = 0; j <= k; ++j)
            parts.push_back(read_har_result(
                path("runs/" + r.id() + "/seed-" + std::to_string(c_.har.seed + static_cast<uint64_t>(j)) + ".jsonl")));
        write_file_atomic(path("har/" + r.id() + ".json"),
                          har_result_json(merge_har_results(parts), "trained on " + r.source->name + "'s synthetic " +
                                                                        r.set->name + ", tested on " + r.set->dataset));
    }

    static std::string ceiling_description(const ExperimentRealSet& set) {
        const std::string how = set.ceiling_folds > 0 ? std::to_string(set.ceiling_folds) + "-fold leave-subjects-out"
                                                      : "leave-one-subject-out";
        return how + " on " + set.dataset + " (real-to-real ceiling)";
    }

    // Real-to-real on the classes the first source's comparison kept, so the ceiling and the rows score the same task.
    void ceiling(const ExperimentRealSet& set) {
        const std::string file = path("har/ceiling-" + set.name + ".json");
        if (set.ceiling_folds < 0 || fs::exists(file)) return;
        const Row& first = *std::find_if(rows_.begin(), rows_.end(), [&](const Row& r) { return r.set == &set; });
        std::map<std::string, std::string> keep;
        for (const std::string& c : read_har_result(path("har/" + first.id() + ".json")).classes) keep[c] = c;
        const WindowSet real = relabel(windows(set.dataset, set), keep);
        const HarResult result = leave_one_subject_out(real, one_training(c_.har.seed), set.ceiling_folds);
        write_file_atomic(file, har_result_json(result, ceiling_description(set)));
        say("ceiling " + set.name + ": " + file);
    }

    ExperimentSummary summarise(int rounds) const {
        ExperimentSummary s;
        s.har_repeats = c_.har.repeats, s.har_rounds_done = rounds;
        for (const Row& r : rows_) {
            const HarResult har = read_har_result(path("har/" + r.id() + ".json"));
            const std::string gap = path("gap/" + r.id() + ".json");
            s.rows.push_back({r.source->name, r.source->model, r.set->name, har.classes,
                              1.0 / static_cast<double>(har.classes.size()),
                              score_summary(har, &HarRun::balanced_accuracy), score_summary(har, &HarRun::macro_f1),
                              har.train_windows, har.test_windows, read_domain_gap(gap).overall.balanced_accuracy});
        }
        for (const ExperimentRealSet& set : c_.real_sets) {
            const std::string file = path("har/ceiling-" + set.name + ".json");
            if (!fs::exists(file)) continue;
            const HarResult har = read_har_result(file);
            s.ceilings.push_back(
                {set.name, ceiling_description(set), har.classes, score_summary(har, &HarRun::balanced_accuracy)});
        }
        const std::string change = path("lacc/change.csv");
        if (fs::exists(change)) {
            const CsvTable t = read_csv(change);
            s.lacc_before = c_.lacc.before, s.lacc_after = c_.lacc.after;
            for (size_t i = 0; i < t.rows.size(); ++i)
                s.lacc_groups[t.rows[i][t.column("group")]] = {t.number(i, t.column("samples")),
                                                               t.number(i, t.column("change_percent"))};
        }
        return s;
    }

    const ExperimentConfig& c_;
    std::string out_;
    std::function<void(const std::string&)> log_;
    std::vector<Row> rows_;
    std::map<std::string, WindowSet> windows_;
    std::map<std::string, std::vector<ImuRecording>> real_recordings_;
};

}  // namespace

std::string experiment_row_name(const ExperimentSource& source, const ExperimentRealSet& set) {
    return source.name + "-" + set.name;
}

ExperimentPlan plan_experiment(const ExperimentConfig& config, const std::string& out) {
    ExperimentPlan plan{config, out, {}};
    for (size_t set = 0; set < config.real_sets.size(); ++set)
        for (size_t source = 0; source < config.sources.size(); ++source) {
            const ExperimentRealSet& r = config.real_sets[set];
            SynthOptions o = config.synth;
            o.prompts = r.prompts;
            o.model = config.sources[source].model;
            o.sensors = r.sensors;
            if (!r.realism.empty()) o.realism = r.realism;
            o.out = (fs::path(out) / "synth" / experiment_row_name(config.sources[source], r)).string();
            try {
                plan.rows.push_back({source, set, plan_synth(o)});
            } catch (const Error& e) {
                throw Error(config.path.empty() ? "experiment" : config.path,
                            "the synthesis of source " + config.sources[source].name + " for real set " + r.name,
                            "settings t2imu synth accepts", e.what());
            }
        }
    return plan;
}

ExperimentSummary run_experiment(const ExperimentPlan& plan, const std::function<void(const std::string&)>& log) {
    claim_output_folder(plan.out);  // marked as t2imu's: a rerun continues in it (core/output_path.hpp)
    return Experiment(plan, log).run();
}

}  // namespace t2imu
