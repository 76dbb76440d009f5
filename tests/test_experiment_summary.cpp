// experiment_summary.cpp: experiment_summary_markdown on a hand-made summary.json: rows per source in order of
// first appearance, columns per real set in config order (with their class counts), balanced accuracy as
// "mean ± sd % (runs)" in percent, an empty cell where a source lacks a set, the ceilings and chance rows, the
// two-sample test to three decimals, and the L_acc table with signed changes (only when the summary has one).
#include <gtest/gtest.h>

#include "pipeline/experiment.hpp"
#include "test_util.hpp"

using namespace t2imu;
using nlohmann::json;

namespace {
json score(double mean, double sd, int runs) { return {{"mean", mean}, {"sd", sd}, {"runs", std::vector<double>(static_cast<size_t>(runs), mean)}}; }

json row(const std::string& source, const std::string& model, const std::string& set, int classes, json ba, double chance, double two_sample) {
    std::vector<std::string> names;
    for (int k = 0; k < classes; ++k) names.push_back("c" + std::to_string(k));
    return {{"source", source}, {"model", model}, {"real_set", set}, {"classes", names}, {"balanced_accuracy", ba},
            {"chance", chance}, {"two_sample_balanced_accuracy", two_sample}};
}

json summary(bool with_lacc) {
    json s = {{"har_rounds_done", 2}, {"har_repeats", 10}};
    s["rows"] = {row("mdm", "models/default", "sisfall", 4, score(0.526, 0.031, 2), 0.25, 0.91234),
                 row("mdm", "models/default", "umafall", 8, score(0.4, 0.0, 2), 0.125, 0.8),
                 row("retrieval", "retrieval:data", "sisfall", 4, score(0.61, 0.0456, 1), 0.25, 0.5)};
    s["ceilings"] = {{{"real_set", "umafall"}, {"balanced_accuracy", score(0.9, 0.02, 4)}}};
    if (with_lacc)
        s["lacc"] = {{"before", "mdm"}, {"after", "mdm_lacc"},
                     {"groups", {{"Running", {{"samples", 12}, {"change_percent", -12.74}}}, {"all", {{"samples", 30}, {"change_percent", 3.04}}}}}};
    return s;
}

}  // namespace

TEST(ExperimentSummary, HarTableInPercentWithRunsAndClassCounts) {
    const std::string md = experiment_summary_markdown(summary(false));
    EXPECT_TRUE(test::contains(md, "2 of 10 repeats done.")) << md;
    EXPECT_TRUE(test::contains(md, "| training data | sisfall (4 classes) | umafall (8 classes) |\n|---|---|---|\n")) << md;
    // 0.526 ± 0.031 over 2 runs; retrieval has no umafall cell.
    EXPECT_TRUE(test::contains(md, "| mdm (models/default) | 52.6 ± 3.1 % (2) | 40.0 ± 0.0 % (2) |\n")) << md;
    EXPECT_TRUE(test::contains(md, "| retrieval (retrieval:data) | 61.0 ± 4.6 % (1) |  |\n")) << md;
    EXPECT_TRUE(test::contains(md, "| real-to-real ceiling (real training data) |  | 90.0 ± 2.0 % (4) |\n")) << md;
    EXPECT_TRUE(test::contains(md, "| chance | 25.0 % | 12.5 % |\n")) << md;  // 1/4 and 1/8
}

TEST(ExperimentSummary, TwoSampleTableAndOptionalLacc) {
    const std::string without = experiment_summary_markdown(summary(false));
    EXPECT_TRUE(test::contains(without, "| training data | sisfall | umafall |\n")) << without;  // no class counts here
    EXPECT_TRUE(test::contains(without, "| mdm | 0.912 | 0.800 |\n")) << without;
    EXPECT_TRUE(test::contains(without, "| retrieval | 0.500 |  |\n")) << without;
    EXPECT_FALSE(test::contains(without, "## L_acc"));
    const std::string with = experiment_summary_markdown(summary(true));
    EXPECT_TRUE(test::contains(with, "## L_acc of mdm_lacc against mdm on the same clips and draws, per activity category")) << with;
    EXPECT_TRUE(test::contains(with, "| Running | 12 | -12.7 % |\n")) << with;
    EXPECT_TRUE(test::contains(with, "| all | 30 | +3.0 % |\n")) << with;
}
