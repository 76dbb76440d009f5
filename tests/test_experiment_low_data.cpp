// experiment_low_data.cpp: the [low_data] section read and checked (through read_experiment_config), and the table
// of low-data/summary.md.
#include <gtest/gtest.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "pipeline/experiment.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

const char* kBase =
    "[[source]]\nname = \"mdm\"\nmodel = \"models/default\"\n"
    "[[real]]\nname = \"sisfall\"\ndataset = \"data/sisfall\"\nprompts = \"prompts/sisfall.tsv\"\nsensors = "
    "\"sisfall\"\n";

ExperimentConfig read_with(const std::string& low_data) {
    const std::string path = test::scratch_dir("experiment_low_data") + "/c.toml";
    write_file_atomic(path, std::string(kBase) + "[low_data]\n" + low_data);
    return read_experiment_config(path);
}

}  // namespace

TEST(ExperimentLowData, EveryKeyLandsInItsField) {
    const ExperimentLowData l =
        read_with(
            "train_subjects = [\"0\", \"2\", \"all\"]\nall_test_subjects = 3\ndraws = "
            "7\nprotocols = [\"finetune\"]\nsynthetic_share = 0.25\n"
            "finetune_epochs = 0\nfinetune_learning_rate = 0.001\nfinetune_synthetic_share = 0.3\n")
            .low_data;
    EXPECT_EQ(l.train_subjects, (std::vector<int>{0, 2, ExperimentLowData::kAllSubjects}));
    EXPECT_EQ(l.all_test_subjects, 3);
    EXPECT_EQ(l.draws, 7);
    EXPECT_EQ(l.protocols, (std::vector<HarProtocol>{HarProtocol::finetune}));
    EXPECT_EQ(l.synthetic_share, 0.25);
    EXPECT_EQ(l.finetune_epochs, 0);
    EXPECT_EQ(l.finetune_learning_rate, 0.001);
    EXPECT_EQ(l.finetune_synthetic_share, 0.3);
    // Absent: no curve, and the defaults.
    const ExperimentLowData none = read_with("").low_data;
    EXPECT_TRUE(none.train_subjects.empty());
    EXPECT_EQ(none.draws, 5);
    EXPECT_EQ(none.protocols.size(), 2u);
}

TEST(ExperimentLowData, RefusesEachRuleNamingTheField) {
    for (const auto& [text, field] : std::vector<std::pair<std::string, std::string>>{
             {"train_subjects = [\"1\", \"some\"]\n", "low_data.train_subjects"},
             {"train_subjects = [\"-2\"]\n", "low_data.train_subjects"},
             {"draws = 0\n", "low_data.draws"},
             {"all_test_subjects = 0\n", "low_data.all_test_subjects"},
             {"protocols = [\"blend\"]\n", "low_data.protocols"},
             {"synthetic_share = 1\n", "low_data.synthetic_share"},
             {"finetune_epochs = -1\n", "low_data.finetune_epochs"},
             {"finetune_learning_rate = 0\n", "low_data.finetune_learning_rate"},
             {"finetune_synthetic_share = -0.1\n", "low_data.finetune_synthetic_share"},
             {"shares = 0.5\n", "low_data.shares"}}) {
        const std::string e = test::error_message([&] { read_with(text); });
        EXPECT_TRUE(test::contains(e, field)) << text << ": " << e;
    }
}

TEST(ExperimentLowData, ShippedConfigReads) {
    const ExperimentConfig c = read_experiment_config(std::string(T2IMU_SOURCE_DIR) + "/experiments/low-data.toml");
    EXPECT_EQ(c.low_data.train_subjects, (std::vector<int>{0, 1, 2, 4, 8, ExperimentLowData::kAllSubjects}));
    EXPECT_GE(c.low_data.draws, 5);  // the bar: at least 5 draws per K
    EXPECT_EQ(c.real_sets.size(), 2u);
    ASSERT_EQ(c.sources.size(), 2u);  // the item 4: the curve for the learned model and for retrieval
    EXPECT_EQ(c.sources[0].model, "models/default");
    EXPECT_EQ(c.sources[1].model, "retrieval:cache/dataset");
}

TEST(ExperimentLowData, TableHasEveryArmAndTheGain) {
    LowDataCurve c{"sisfall", {"lying", "walking"}, {"0", "1"}, {}};
    c.arms.push_back({"real only", {{"1", 1, {0.6, 0.7}}}});
    c.arms.push_back({"mdm mix", {{"0", 0, {0.75}}, {"1", 1, {0.8, 0.84}}}});
    c.arms.push_back({"mdm finetune", {{"0", 0, {0.75}}, {"1", 1, {0.7, 0.72}}}});
    const std::string md = low_data_markdown({c});
    EXPECT_TRUE(test::contains(md, "| K | real only | mdm mix | mdm finetune | best synthetic arm − real only |"))
        << md;
    EXPECT_TRUE(test::contains(md, "| 1 | 65.0 ± 7.1 (2) | 82.0 ± 2.8 (2) | 71.0 ± 1.4 (2) | +17.0 |")) << md;
    EXPECT_TRUE(test::contains(md, "| 0 |  | 75.0 ± 0.0 (1) | 75.0 ± 0.0 (1) |  |")) << md;
    EXPECT_TRUE(test::contains(md, "- mdm mix, K = 1 (1 subject): 80.0 84.0")) << md;
}
