// DDPM arithmetic against the official sampler: replaying the recorded x0 estimates and noises of
// shared/data/reference/mdm/ddpm_sample_T50 must give every recorded step and the final sample.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include "core/npy.hpp"
#include "diffusion/gaussian_diffusion.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

torch::Tensor load(const std::string& name) {
    const NdArray a = read_npy(test::shared_path("reference/mdm/ddpm_sample_T50/" + name + ".npy"));
    std::vector<float> v = a.to<float>();
    return torch::from_blob(v.data(), a.shape, torch::kFloat).clone();
}

}  // namespace

TEST(GaussianDiffusion, ReplaysTheOfficialDdpmLoop) {
    std::string x_t_path;
    SHARED_OR_SKIP(x_t_path, "reference/mdm/ddpm_sample_T50/x_T.npy");
    const GaussianDiffusion d(cosine_schedule(50));
    const torch::Tensor x_in = load("step_x_in"), x0 = load("step_pred_xstart"), noise = load("step_noise");
    const torch::Tensor mean_ref = load("step_mean");
    const std::vector<int64_t> steps =
        read_npy(test::shared_path("reference/mdm/ddpm_sample_T50/step_t.npy")).to<int64_t>();
    ASSERT_EQ(steps.size(), 50u);
    torch::Tensor x = load("x_T");
    double worst_mean = 0, worst_x = 0;
    for (int64_t i = 0; i < 50; ++i) {
        const torch::Tensor t = torch::tensor({steps[static_cast<size_t>(i)]});
        worst_x = std::max(worst_x, (x - x_in[i]).abs().max().item<double>());
        worst_mean =
            std::max(worst_mean, (d.posterior_mean(x0[i], x_in[i], t) - mean_ref[i]).abs().max().item<double>());
        x = d.p_sample_step(x_in[i], x0[i], t, noise[i]);
    }
    EXPECT_EQ(steps.front(), 49);
    EXPECT_LT(worst_mean, 1e-5);
    EXPECT_LT(worst_x, 1e-5);
    EXPECT_LT((x - load("final_sample")).abs().max().item<double>(), 1e-5);
}

TEST(GaussianDiffusion, QSampleEndpoints) {
    const GaussianDiffusion d(cosine_schedule(1000));
    const torch::Tensor x0 = torch::ones({2, 3}), noise = torch::full({2, 3}, 2.0);
    const torch::Tensor xt = d.q_sample(x0, torch::tensor({int64_t{0}, int64_t{999}}), noise);
    // t = 0 keeps x0 almost untouched; t = T-1 is almost pure noise (abar ~ 0).
    EXPECT_NEAR(xt[0][0].item<float>(), 1.0f, 0.02f);
    EXPECT_NEAR(xt[1][0].item<float>(), 2.0f, 0.01f);
    EXPECT_THROW(d.q_sample(x0, torch::tensor({int64_t{0}, int64_t{1000}}), noise), Error);
}
