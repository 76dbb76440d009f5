// The sampler comparison on a tiny trained model: the reference against itself is distance 0 and ratio 1 (the
// same seeds give the same motions), another sampler differs, captured clips make a last row, and the
// configuration list is parsed strictly.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cmath>

#include "core/error.hpp"
#include "diffusion/trainer.hpp"
#include "pipeline/sampler_comparison.hpp"
#include "test_util.hpp"
#include "tiny_model.hpp"

using namespace t2imu;

TEST(SamplerComparison, ParsesTheSamplerList) {
    const std::vector<SamplerConfig> c = parse_sampler_configs("ddpm,ddim:20,dpmpp:5");
    ASSERT_EQ(c.size(), 3u);
    EXPECT_EQ(c[0].name(), "ddpm");
    EXPECT_EQ(c[1].sampler, Sampler::ddim);
    EXPECT_EQ(c[1].steps, 20);
    EXPECT_EQ(c[2].name(), "dpmpp:5");
    for (const char* bad : {"ddpm:5", "ddim", "euler:3", "ddim:1", "dpmpp:x", ""})
        EXPECT_THROW(parse_sampler_configs(bad), Error) << bad;
}

TEST(SamplerComparison, OptionsAreCheckedBeforeAnyModelIsLoaded) {
    SamplerComparisonOptions o;
    o.model = "no-such-model";  // validate() reads nothing
    EXPECT_NO_THROW(o.validate());
    o.guidance = std::nan("");
    EXPECT_NE(test::error_message([&] { o.validate(); }).find("--guidance"), std::string::npos);
    o.guidance = 2.5;
    o.frames = 197;
    EXPECT_NE(test::error_message([&] { o.validate(); }).find("--frames"), std::string::npos);
    o.frames = 120;
    o.samples_per_prompt = 0;
    EXPECT_NE(test::error_message([&] { o.validate(); }).find("--samples-per-prompt"), std::string::npos);
}

TEST(SamplerComparison, SameSeedsGiveTheSameMotionsAndOtherSamplersDiffer) {
    torch::set_num_threads(1);
    const std::string dir = test::scratch_dir("sampler_comparison");
    const std::string data = test::make_tiny_motion_dataset(dir + "/data");
    train_mdm(read_train_config(test::write_tiny_train_config(dir, data, dir + "/model")), false, "", 10);
    SamplerComparisonOptions o;
    o.model = dir + "/model";
    o.prompts = {{"walking", "a person walks forward slowly"}, {"running", "someone walks"}};
    o.samples_per_prompt = 2;
    o.frames = 30;
    o.batch = 3;
    o.captured_dataset = data;
    o.captured_split = "train";
    const CsvTable t = compare_samplers(o, parse_sampler_configs("ddpm,ddpm,ddim:5"));
    ASSERT_EQ(t.rows.size(), 4u);
    const auto col = [&](const char* name) { return t.column(name); };
    EXPECT_EQ(t.rows[0][col("denoiser_calls")], "50");  // the tiny model's T
    EXPECT_EQ(t.rows[2][col("denoiser_calls")], "5");
    for (size_t r = 0; r < 3; ++r) EXPECT_EQ(t.rows[r][col("motions")], "4");
    for (size_t r : {0, 1}) {
        EXPECT_DOUBLE_EQ(t.number(r, col("descriptor_distance")), 0.0);
        EXPECT_DOUBLE_EQ(t.number(r, col("feature_acc_energy_ratio")), 1.0);
        EXPECT_DOUBLE_EQ(t.number(r, col("joint_acc_rms_ratio")), 1.0);
    }
    EXPECT_GT(t.number(2, col("descriptor_distance")), 0.0);
    EXPECT_TRUE(std::isfinite(t.number(2, col("descriptor_distance"))));
    EXPECT_NE(t.number(2, col("feature_acc_energy_ratio")), 1.0);
    EXPECT_GT(t.number(0, col("feature_acc_energy")), 0.0);
    EXPECT_TRUE(std::isnan(t.number(0, col("activity_pass_rate"))));  // no activity reference given
    // The captured row: the tiny set's six 60-frame cuts of a slow walk, every one within the quality limits.
    EXPECT_EQ(t.rows[3][col("sampler")], "captured:train");
    EXPECT_EQ(t.rows[3][col("motions")], "6");
    EXPECT_DOUBLE_EQ(t.number(3, col("quality_failure_rate")), 0.0);
    EXPECT_LT(t.number(3, col("joint_acc_rms_m_s2")), 20.0);
}
