// The experiment's low-data curve (pipeline/experiment.hpp, ExperimentLowData): its TOML section, its trainings and
// its table.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"
#include "core/toml_section.hpp"
#include "pipeline/experiment.hpp"

namespace t2imu {

namespace fs = std::filesystem;

ExperimentLowData read_experiment_low_data(TomlSection s, const std::string& path) {
    ExperimentLowData l;
    std::vector<std::string> ks, protocols;
    s.read("train_subjects", ks);
    for (const std::string& k : ks)
        l.train_subjects.push_back(k == "all"
                                       ? ExperimentLowData::kAllSubjects
                                       : static_cast<int>(integer_in(k, 0, 100000, path, "low_data.train_subjects")));
    s.read("all_test_subjects", l.all_test_subjects);
    s.read("draws", l.draws);
    if (s.has("protocols")) {
        s.read("protocols", protocols);
        l.protocols.clear();
        for (const std::string& p : protocols) {
            if (p != "mix" && p != "finetune") throw Error(path, "low_data.protocols", "mix or finetune", p);
            l.protocols.push_back(parse_har_protocol(p, "low_data.protocols"));
        }
    }
    s.read("synthetic_share", l.synthetic_share);
    s.read("finetune_epochs", l.finetune_epochs);
    s.read("finetune_learning_rate", l.finetune_learning_rate);
    s.read("finetune_synthetic_share", l.finetune_synthetic_share);
    s.refuse_unknown_keys();
    if (l.all_test_subjects < 1)
        throw Error(path, "low_data.all_test_subjects", "at least 1 subject", std::to_string(l.all_test_subjects));
    if (l.draws < 1) throw Error(path, "low_data.draws", "at least 1 draw", std::to_string(l.draws));
    if (!(l.synthetic_share >= 0 && l.synthetic_share < 1))
        throw Error(path, "low_data.synthetic_share", "0 (by windows) to below 1", std::to_string(l.synthetic_share));
    if (!(l.finetune_synthetic_share >= 0 && l.finetune_synthetic_share < 1))
        throw Error(path, "low_data.finetune_synthetic_share", "0 (the drawn subjects alone) to below 1",
                    std::to_string(l.finetune_synthetic_share));
    if (l.finetune_epochs < 0)
        throw Error(path, "low_data.finetune_epochs", "0 or more epochs", std::to_string(l.finetune_epochs));
    if (!(l.finetune_learning_rate > 0 && l.finetune_learning_rate < 1))
        throw Error(path, "low_data.finetune_learning_rate", "a learning rate above 0, below 1",
                    std::to_string(l.finetune_learning_rate));
    return l;
}

namespace {

std::string label_of(int k) { return k == ExperimentLowData::kAllSubjects ? "all" : std::to_string(k); }

class LowDataRun {
public:
    LowDataRun(const ExperimentConfig& c, std::string out,
               const std::function<const WindowSet&(const std::string&, const ExperimentRealSet&)>& windows,
               const std::function<void(const std::string&)>& log)
        : c_(c), out_(std::move(out)), windows_(windows), log_(log) {}

    LowDataCurve curve(const ExperimentRealSet& set) {
        const std::string first_row = experiment_row_name(c_.sources.front(), set);
        LowDataCurve curve{set.name, read_har_result(path("har/" + first_row + ".json")).classes, {}, {}};
        // Real only and every synthetic arm score the classes of the first source's synthetic-only row.
        std::map<std::string, std::string> keep;
        for (const std::string& cls : curve.classes) keep[cls] = cls;
        const WindowSet& real =
            real_windows_.emplace(set.name, relabel(windows_(set.dataset, set), keep)).first->second;
        const size_t subjects = std::set<std::string>(real.subjects.begin(), real.subjects.end()).size();
        for (int k : c_.low_data.train_subjects) curve.labels.push_back(label_of(k));
        LowDataArm real_only{"real only", {}};
        for (int k : c_.low_data.train_subjects) {
            if (k == 0) continue;
            const int n = count(k, subjects, set);
            real_only.points.push_back(
                step(path("low-data/real-" + set.name + "/real-k" + label_of(k) + ".json"), label_of(k),
                     "real only: " + std::to_string(n) + " drawn subjects of " + set.dataset,
                     [&](const HarCheckpoint& checkpoint) {
                         return train_on_sets({{&real, set.dataset}}, real, draws(), sets(HarProtocol::mix, 0, n),
                                              nullptr, &checkpoint);
                     }));
        }
        curve.arms.push_back(real_only);
        for (const ExperimentSource& source : c_.sources) {
            const std::string row = experiment_row_name(source, set);
            const WindowSet& synthetic = windows_(path("synth/" + row), set);
            for (HarProtocol protocol : c_.low_data.protocols) {
                HarPretrained pretrained;  // one pretraining for every K of this arm
                LowDataArm arm{source.name + " " + har_protocol_name(protocol), {}};
                for (int k : c_.low_data.train_subjects) {
                    if (k == 0) {  // synthetic only: the experiment's row
                        arm.points.push_back(low_data_point(read_har_result(path("har/" + row + ".json")), "0"));
                        continue;
                    }
                    const int n = count(k, subjects, set);
                    const std::string file =
                        path("low-data/" + row + "/" + har_protocol_name(protocol) + "-k" + label_of(k) + ".json");
                    const std::string description = std::string(har_protocol_name(protocol)) + ": " + source.name +
                                                    "'s synthetic " + set.name + " and " + std::to_string(n) +
                                                    " drawn subjects of " + set.dataset;
                    arm.points.push_back(step(file, label_of(k), description, [&](const HarCheckpoint& checkpoint) {
                        return train_on_sets({{&synthetic, path("synth/" + row)}, {&real, set.dataset}}, real, draws(),
                                             sets(protocol, 1, n), &pretrained, &checkpoint);
                    }));
                }
                curve.arms.push_back(arm);
            }
        }
        return curve;
    }

private:
    std::string path(const std::string& relative) const { return (fs::path(out_) / relative).string(); }

    int count(int k, size_t subjects, const ExperimentRealSet& set) const {
        const int n =
            k == ExperimentLowData::kAllSubjects ? static_cast<int>(subjects) - c_.low_data.all_test_subjects : k;
        if (n < 1 || static_cast<size_t>(n) >= subjects)
            throw Error("experiment", "low_data.train_subjects",
                        "K from 1 to " + std::to_string(subjects - 1) + " for " + set.name, label_of(k));
        return n;
    }

    HarOptions draws() const {
        HarOptions o = c_.har;
        o.repeats = c_.low_data.draws;
        return o;
    }

    SeveralSetsOptions sets(HarProtocol protocol, int test_set, int n) const {
        SeveralSetsOptions m;
        m.protocol = protocol;
        m.test_set = test_set;
        m.train_subjects = n;
        const double share =
            protocol == HarProtocol::mix ? c_.low_data.synthetic_share : c_.low_data.finetune_synthetic_share;
        if (test_set == 1 && share > 0) m.shares = {share, 1 - share};
        m.finetune_epochs = c_.low_data.finetune_epochs;
        m.finetune_learning_rate = c_.low_data.finetune_learning_rate;
        return m;
    }

    // A point's draws, each kept in FILE.partial as it ends (a stop loses at most one training), then FILE.
    template <class Train>
    LowDataPoint step(const std::string& file, const std::string& label, const std::string& description,
                      const Train& train) {
        if (!fs::exists(file)) {
            const std::string partial = file + ".partial";
            HarCheckpoint checkpoint;
            if (fs::exists(partial)) checkpoint.done = read_har_result(partial);
            checkpoint.save = [&](const HarResult& so_far) {
                write_file_atomic(partial, har_result_json(so_far, description + " (so far)"));
            };
            write_file_atomic(file, har_result_json(train(checkpoint), description));
            fs::remove(partial);
            if (log_) log_("low-data " + file);
        }
        return low_data_point(read_har_result(file), label);
    }

    const ExperimentConfig& c_;
    std::string out_;
    std::function<const WindowSet&(const std::string&, const ExperimentRealSet&)> windows_;
    std::function<void(const std::string&)> log_;
    std::map<std::string, WindowSet> real_windows_;
};

std::string percent(const LowDataPoint* p) {
    if (!p) return "";
    const ScoreSummary s = p->balanced_accuracy();
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.1f ± %.1f (%zu)", 100 * s.mean, 100 * s.sd, s.runs.size());
    return buf;
}

}  // namespace

std::vector<LowDataCurve> run_low_data(
    const ExperimentConfig& c, const std::string& out,
    const std::function<const WindowSet&(const std::string&, const ExperimentRealSet&)>& windows,
    const std::function<void(const std::string&)>& log) {
    LowDataRun run(c, out, windows, log);
    std::vector<LowDataCurve> curves;
    for (const ExperimentRealSet& set : c.real_sets) curves.push_back(run.curve(set));
    write_file_atomic((fs::path(out) / "low-data/curves.json").string(), low_data_curves_json(curves).dump(2) + "\n");
    write_file_atomic((fs::path(out) / "low-data/summary.md").string(), low_data_markdown(curves));
    return curves;
}

std::string low_data_markdown(const std::vector<LowDataCurve>& curves) {
    std::string md;
    for (const LowDataCurve& c : curves) {
        md += "## " + c.real_set + ": balanced accuracy (%) against K real training subjects\n\n";
        md +=
            "mean ± sd over the draws of subjects (their number in brackets), tested on the subjects not drawn; K = 0 "
            "is "
            "synthetic only.\n\n| K |";
        std::string rule = "|---|";
        for (const LowDataArm& a : c.arms) md += " " + a.name + " |", rule += "---|";
        md += " best synthetic arm − real only |\n" + rule + "---|\n";
        for (const std::string& label : c.labels) {
            md += "| " + label + " |";
            double best = -1;
            for (const LowDataArm& a : c.arms) {
                md += " " + percent(a.at(label)) + " |";
                if (&a != &c.arms.front() && a.at(label)) best = std::max(best, a.at(label)->balanced_accuracy().mean);
            }
            const LowDataPoint* real = c.arms.front().at(label);
            char gain[32] = "";
            if (real && best >= 0)
                std::snprintf(gain, sizeof gain, "%+.1f", 100 * (best - real->balanced_accuracy().mean));
            md += " " + std::string(gain) + " |\n";
        }
        md += "\nEach draw (balanced accuracy, %):\n\n";
        for (const LowDataArm& a : c.arms)
            for (const LowDataPoint& p : a.points) {
                md += "- " + a.name + ", K = " + p.label + " (" + std::to_string(p.train_subjects) +
                      (p.train_subjects == 1 ? " subject):" : " subjects):");
                for (double d : p.draws) {
                    char buf[16];
                    std::snprintf(buf, sizeof buf, " %.1f", 100 * d);
                    md += buf;
                }
                md += "\n";
            }
        md += "\n";
    }
    return md;
}

}  // namespace t2imu
