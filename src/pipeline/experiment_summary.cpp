// summary.md of the experiment (pipeline/experiment.hpp): the tables README and the model cards quote.
#include <algorithm>
#include <cstdio>
#include <map>

#include "pipeline/experiment.hpp"

namespace t2imu {

namespace {

std::string percent(const nlohmann::json& score) {
    char buf[96];
    const size_t n = score["runs"].size();
    std::snprintf(buf, sizeof buf, "%.1f ± %.1f %% (%zu)", 100 * score["mean"].get<double>(), 100 * score["sd"].get<double>(), n);
    return buf;
}

std::string number(double v, const char* format) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

// Real set names in config order, as the rows list them.
std::vector<std::string> real_sets(const nlohmann::json& s) {
    std::vector<std::string> sets;
    for (const auto& r : s["rows"])
        if (std::find(sets.begin(), sets.end(), r["real_set"].get<std::string>()) == sets.end()) sets.push_back(r["real_set"]);
    return sets;
}

std::string table_head(const std::string& first, const std::vector<std::string>& sets, const nlohmann::json& s, bool classes) {
    std::string head = "| " + first + " |", rule = "|---|";
    for (const std::string& set : sets) {
        std::string label = set;
        for (const auto& r : s["rows"])
            if (classes && r["real_set"] == set) label = set + " (" + std::to_string(r["classes"].size()) + " classes)";
        head += " " + label + " |";
        rule += "---|";
    }
    return head + "\n" + rule + "\n";
}

}  // namespace

std::string experiment_summary_markdown(const nlohmann::json& s) {
    const std::vector<std::string> sets = real_sets(s);
    std::map<std::string, std::map<std::string, const nlohmann::json*>> cell;  // source -> set -> row
    std::vector<std::string> sources;
    for (const auto& r : s["rows"]) {
        const std::string source = r["source"];
        if (!cell.count(source)) sources.push_back(source);
        cell[source][r["real_set"]] = &r;
    }
    std::string md = "## Synthetic-to-real HAR: DeepConvLSTM trained only on synthetic data, balanced accuracy on the real set\n\n";
    md += "mean ± sd over the trainings (their number in brackets); " + std::to_string(s["har_rounds_done"].get<int>()) + " of " +
          std::to_string(s["har_repeats"].get<int>()) + " repeats done.\n\n";
    md += table_head("training data", sets, s, true);
    for (const std::string& source : sources) {
        md += "| " + source + " (" + cell[source].begin()->second->at("model").get<std::string>() + ") |";
        for (const std::string& set : sets) md += " " + (cell[source].count(set) ? percent((*cell[source][set])["balanced_accuracy"]) : "") + " |";
        md += "\n";
    }
    md += "| real-to-real ceiling (real training data) |";
    for (const std::string& set : sets) {
        std::string v;
        for (const auto& c : s["ceilings"])
            if (c["real_set"] == set) v = percent(c["balanced_accuracy"]);
        md += " " + v + " |";
    }
    md += "\n| chance |";
    for (const std::string& set : sets) md += " " + number(100 * (*cell[sources[0]][set])["chance"].get<double>(), "%.1f %%") + " |";
    md += "\n\nPaper (RealWorld, 8 classes, 10 repeats): MDM 52.6 %, MDM + L_acc 57.2 %.\n\n";

    md += "## Real vs synthetic: classifier two-sample test on catch22 features (balanced accuracy; 0.5 = indistinguishable)\n\n";
    md += table_head("training data", sets, s, false);
    for (const std::string& source : sources) {
        md += "| " + source + " |";
        for (const std::string& set : sets)
            md += " " + (cell[source].count(set) ? number((*cell[source][set])["two_sample_balanced_accuracy"].get<double>(), "%.3f") : "") + " |";
        md += "\n";
    }
    if (s.contains("lacc")) {
        const auto& l = s["lacc"];
        md += "\n## L_acc of " + l["after"].get<std::string>() + " against " + l["before"].get<std::string>() +
              " on the same clips and draws, per activity category\n\n| category | samples | change |\n|---|---|---|\n";
        for (const auto& [group, g] : l["groups"].items())
            md += "| " + group + " | " + number(g["samples"].get<double>(), "%.0f") + " | " + number(g["change_percent"].get<double>(), "%+.1f %%") + " |\n";
        md += "\nPaper (HumanML3D test set): L_acc −12.7 %.\n";
    }
    return md;
}

}  // namespace t2imu
