// The cosine schedule against the official GaussianDiffusion (shared/data/reference/mdm/schedule_cosine_T*).
#include <gtest/gtest.h>

#include <cmath>

#include "core/npy.hpp"
#include "diffusion/noise_schedule.hpp"
#include "test_util.hpp"

using namespace t2imu;

class CosineSchedule : public ::testing::TestWithParam<int> {};

TEST_P(CosineSchedule, MatchesTheOfficialArrays) {
    const int steps = GetParam();
    const std::string dir = "reference/mdm/schedule_cosine_T" + std::to_string(steps);
    std::string betas_path;
    SHARED_OR_SKIP(betas_path, dir + "/betas.npy");
    const NoiseSchedule s = cosine_schedule(steps);
    const std::pair<const char*, const std::vector<double>*> arrays[] = {
        {"betas", &s.betas},
        {"alphas_cumprod", &s.alphas_cumprod},
        {"alphas_cumprod_prev", &s.alphas_cumprod_prev},
        {"alphas_cumprod_next", &s.alphas_cumprod_next},
        {"sqrt_alphas_cumprod", &s.sqrt_alphas_cumprod},
        {"sqrt_one_minus_alphas_cumprod", &s.sqrt_one_minus_alphas_cumprod},
        {"log_one_minus_alphas_cumprod", &s.log_one_minus_alphas_cumprod},
        {"sqrt_recip_alphas_cumprod", &s.sqrt_recip_alphas_cumprod},
        {"sqrt_recipm1_alphas_cumprod", &s.sqrt_recipm1_alphas_cumprod},
        {"posterior_variance", &s.posterior_variance},
        {"posterior_log_variance_clipped", &s.posterior_log_variance_clipped},
        {"posterior_mean_coef1", &s.posterior_mean_coef1},
        {"posterior_mean_coef2", &s.posterior_mean_coef2},
    };
    for (const auto& [name, ours] : arrays) {
        const std::vector<double> expected = read_npy(test::shared_path(dir + "/" + name + ".npy")).to<double>();
        ASSERT_EQ(ours->size(), expected.size()) << name;
        for (size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR((*ours)[i], expected[i], 1e-12 * std::max(1.0, std::fabs(expected[i])))
                << name << "[" << i << "]";
    }
}

INSTANTIATE_TEST_SUITE_P(Steps, CosineSchedule, ::testing::Values(50, 1000));

TEST(NoiseSchedule, RefusesDegenerateBetas) {
    EXPECT_THROW(cosine_schedule(1), Error);
    EXPECT_THROW(schedule_from_betas({0.1, 0.0, 0.2}), Error);
}
