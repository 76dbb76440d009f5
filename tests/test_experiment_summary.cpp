// experiment_summary.cpp: summary.json's fields, and experiment_summary_markdown on a hand-made summary: rows per
// source in order of first appearance, columns per real set in config order (with their class counts), balanced
// accuracy as "mean ± sd % (runs)" in percent, an empty cell where a source lacks a set, the ceilings and chance rows,
// the two-sample test to three decimals, and the L_acc table with signed changes (only when the summary has one).
#include <gtest/gtest.h>

#include "pipeline/experiment.hpp"
#include "test_util.hpp"

using namespace t2imu;
using nlohmann::json;

namespace {
ScoreSummary score(double mean, double sd, int runs) {
    return {mean, sd, std::vector<double>(static_cast<size_t>(runs), mean)};
}

ExperimentRow row(const std::string& source, const std::string& model, const std::string& set, int classes,
                  ScoreSummary ba, double chance, double two_sample) {
    ExperimentRow r;
    r.source = source, r.model = model, r.real_set = set, r.chance = chance, r.balanced_accuracy = ba,
    r.two_sample_balanced_accuracy = two_sample;
    for (int k = 0; k < classes; ++k) r.classes.push_back("c" + std::to_string(k));
    return r;
}

ExperimentSummary summary(bool with_lacc) {
    ExperimentSummary s;
    s.har_rounds_done = 2, s.har_repeats = 10;
    s.rows = {row("mdm", "models/default", "sisfall", 4, score(0.526, 0.031, 2), 0.25, 0.91234),
              row("mdm", "models/default", "umafall", 8, score(0.4, 0.0, 2), 0.125, 0.8),
              row("retrieval", "retrieval:data", "sisfall", 4, score(0.61, 0.0456, 1), 0.25, 0.5)};
    s.ceilings = {{"umafall", "leave-one-subject-out", {"c0"}, score(0.9, 0.02, 4)}};
    if (with_lacc) {
        s.lacc_before = "mdm", s.lacc_after = "mdm_lacc";
        s.lacc_groups = {{"Running", {12, -12.74}}, {"all", {30, 3.04}}};
    }
    return s;
}

}  // namespace

TEST(ExperimentSummary, HarTableInPercentWithRunsAndClassCounts) {
    const std::string md = experiment_summary_markdown(summary(false));
    EXPECT_TRUE(test::contains(md, "2 of 10 repeats done.")) << md;
    EXPECT_TRUE(test::contains(md, "| training data | sisfall (4 classes) | umafall (8 classes) |\n|---|---|---|\n"))
        << md;
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
    EXPECT_TRUE(
        test::contains(with, "## L_acc of mdm_lacc against mdm on the same clips and draws, per activity category"))
        << with;
    EXPECT_TRUE(test::contains(with, "| Running | 12 | -12.7 % |\n")) << with;
    EXPECT_TRUE(test::contains(with, "| all | 30 | +3.0 % |\n")) << with;
}

TEST(ExperimentSummary, JsonHoldsEveryFieldUnderItsName) {
    const json j = experiment_summary_json(summary(true));
    EXPECT_EQ(j["har_rounds_done"], 2);
    ASSERT_EQ(j["rows"].size(), 3u);
    EXPECT_EQ(j["rows"][0]["balanced_accuracy"], (json{{"mean", 0.526}, {"sd", 0.031}, {"runs", {0.526, 0.526}}}));
    EXPECT_EQ(j["rows"][2]["two_sample_balanced_accuracy"], 0.5);
    EXPECT_EQ(j["ceilings"][0]["description"], "leave-one-subject-out");
    EXPECT_EQ(j["lacc"]["groups"]["Running"]["change_percent"], -12.74);
    EXPECT_FALSE(experiment_summary_json(summary(false)).contains("lacc"));
}
