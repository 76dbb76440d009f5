// summary.json and summary.md of the experiment (pipeline/experiment.hpp): the tables docs/results.md and the model
// cards quote.
#include <algorithm>
#include <cstdio>
#include <map>

#include "pipeline/experiment.hpp"

namespace t2imu {

namespace {

std::string percent(const ScoreSummary& score) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.1f ± %.1f %% (%zu)", 100 * score.mean, 100 * score.sd, score.runs.size());
    return buf;
}

std::string number(double v, const char* format) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

// The paper's own figures, quoted under our tables for comparison: synthetic-to-real HAR on RealWorld (8 classes,
// 10 repeats) without and with L_acc, and L_acc's change on the HumanML3D test set (percent).
constexpr double kPaperHarMdm = 52.6, kPaperHarMdmLacc = 57.2, kPaperLaccChange = -12.7;

// Real set names in config order, as the rows list them.
std::vector<std::string> real_sets(const ExperimentSummary& s) {
    std::vector<std::string> sets;
    for (const ExperimentRow& r : s.rows)
        if (std::find(sets.begin(), sets.end(), r.real_set) == sets.end()) sets.push_back(r.real_set);
    return sets;
}

std::string table_head(const std::string& first, const std::vector<std::string>& sets, const ExperimentSummary& s,
                       bool classes) {
    std::string head = "| " + first + " |", rule = "|---|";
    for (const std::string& set : sets) {
        std::string label = set;
        for (const ExperimentRow& r : s.rows)
            if (classes && r.real_set == set) label = set + " (" + std::to_string(r.classes.size()) + " classes)";
        head += " " + label + " |";
        rule += "---|";
    }
    return head + "\n" + rule + "\n";
}

}  // namespace

nlohmann::json experiment_summary_json(const ExperimentSummary& s) {
    nlohmann::json j = {{"har_repeats", s.har_repeats},
                        {"har_rounds_done", s.har_rounds_done},
                        {"rows", nlohmann::json::array()},
                        {"ceilings", nlohmann::json::array()}};
    for (const ExperimentRow& r : s.rows)
        j["rows"].push_back({{"source", r.source},
                             {"model", r.model},
                             {"real_set", r.real_set},
                             {"classes", r.classes},
                             {"chance", r.chance},
                             {"balanced_accuracy", score_summary_json(r.balanced_accuracy)},
                             {"macro_f1", score_summary_json(r.macro_f1)},
                             {"train_windows", r.train_windows},
                             {"test_windows", r.test_windows},
                             {"two_sample_balanced_accuracy", r.two_sample_balanced_accuracy}});
    for (const ExperimentCeiling& c : s.ceilings)
        j["ceilings"].push_back({{"real_set", c.real_set},
                                 {"description", c.description},
                                 {"classes", c.classes},
                                 {"balanced_accuracy", score_summary_json(c.balanced_accuracy)}});
    if (!s.lacc_before.empty()) {
        nlohmann::json groups = nlohmann::json::object();
        for (const auto& [group, g] : s.lacc_groups)
            groups[group] = {{"samples", g.samples}, {"change_percent", g.change_percent}};
        j["lacc"] = {{"before", s.lacc_before}, {"after", s.lacc_after}, {"groups", groups}};
    }
    return j;
}

std::string experiment_summary_markdown(const ExperimentSummary& s) {
    const std::vector<std::string> sets = real_sets(s);
    std::map<std::string, std::map<std::string, const ExperimentRow*>> cell;  // source -> set -> row
    std::vector<std::string> sources;
    for (const ExperimentRow& r : s.rows) {
        if (!cell.count(r.source)) sources.push_back(r.source);
        cell[r.source][r.real_set] = &r;
    }
    std::string md =
        "## Synthetic-to-real HAR: DeepConvLSTM trained only on synthetic data, balanced accuracy on the real set\n\n";
    md += "mean ± sd over the trainings (their number in brackets); " + std::to_string(s.har_rounds_done) + " of " +
          std::to_string(s.har_repeats) + " repeats done.\n\n";
    md += table_head("training data", sets, s, true);
    for (const std::string& source : sources) {
        md += "| " + source + " (" + cell[source].begin()->second->model + ") |";
        for (const std::string& set : sets)
            md += " " + (cell[source].count(set) ? percent(cell[source][set]->balanced_accuracy) : "") + " |";
        md += "\n";
    }
    md += "| real-to-real ceiling (real training data) |";
    for (const std::string& set : sets) {
        std::string v;
        for (const ExperimentCeiling& c : s.ceilings)
            if (c.real_set == set) v = percent(c.balanced_accuracy);
        md += " " + v + " |";
    }
    md += "\n| chance |";
    for (const std::string& set : sets) md += " " + number(100 * cell[sources[0]][set]->chance, "%.1f %%") + " |";
    md += "\n\nPaper (RealWorld, 8 classes, 10 repeats): MDM " + number(kPaperHarMdm, "%.1f %%") + ", MDM + L_acc " +
          number(kPaperHarMdmLacc, "%.1f %%") + ".\n\n";

    md +=
        "## Real vs synthetic: classifier two-sample test on catch22 features (balanced accuracy; 0.5 = "
        "indistinguishable)\n\n";
    md += table_head("training data", sets, s, false);
    for (const std::string& source : sources) {
        md += "| " + source + " |";
        for (const std::string& set : sets)
            md += " " +
                  (cell[source].count(set) ? number(cell[source][set]->two_sample_balanced_accuracy, "%.3f") : "") +
                  " |";
        md += "\n";
    }
    if (!s.lacc_before.empty()) {
        md += "\n## L_acc of " + s.lacc_after + " against " + s.lacc_before +
              " on the same clips and draws, per activity category\n\n| category | samples | change |\n|---|---|---|\n";
        for (const auto& [group, g] : s.lacc_groups)
            md += "| " + group + " | " + number(g.samples, "%.0f") + " | " + number(g.change_percent, "%+.1f %%") +
                  " |\n";
        md += "\nPaper (HumanML3D test set): L_acc " + number(kPaperLaccChange, "%.1f %%") + ".\n";
    }
    return md;
}

}  // namespace t2imu
