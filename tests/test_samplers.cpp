// Samplers on data whose exact denoiser is known: a single point, and a Gaussian N(mu, s^2), for which
// E[x0 | x_t] = mu + sqrt(abar) s^2 / (abar s^2 + 1 - abar) (x_t - sqrt(abar) mu). Every sampler must turn
// N(0, 1) into N(mu, s^2); the deterministic ones exactly up to their discretisation error.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "diffusion/samplers.hpp"

using namespace t2imu;

namespace {

X0Predictor gaussian_denoiser(const NoiseSchedule& s, double mu, double sd) {
    return [&s, mu, sd](const torch::Tensor& x, const torch::Tensor& t) {
        const double a = s.alphas_cumprod[static_cast<size_t>(t[0].item<int64_t>())];
        const double gain = std::sqrt(a) * sd * sd / (a * sd * sd + 1 - a);
        return mu + gain * (x - std::sqrt(a) * mu);
    };
}

struct Moments {
    double mean, sd;
};
Moments moments(const torch::Tensor& x) { return {x.mean().item<double>(), x.std().item<double>()}; }

NoiseSource seeded_noise(uint64_t seed) {
    auto gen = std::make_shared<torch::Generator>(at::detail::createCPUGenerator(seed));
    return [gen](const torch::Tensor& like) { return torch::randn(like.sizes(), *gen, like.options()); };
}

torch::Tensor start(int n, uint64_t seed) {
    return torch::randn({n}, at::detail::createCPUGenerator(seed), torch::kFloat64);
}

}  // namespace

TEST(Samplers, TimestepsAreDescendingFromTMinusOneToZero) {
    EXPECT_EQ(sampling_timesteps(1000, 5), (std::vector<int>{999, 562, 250, 62, 0}));  // quadratic spacing
    EXPECT_EQ(sampling_timesteps(10, 10), (std::vector<int>{9, 8, 7, 6, 5, 4, 3, 2, 1, 0}));
    EXPECT_THROW(sampling_timesteps(10, 11), Error);
}

TEST(Samplers, APointDistributionIsReachedExactly) {
    const NoiseSchedule s = cosine_schedule(100);
    const GaussianDiffusion diffusion(s);
    const X0Predictor point = gaussian_denoiser(s, 0.7, 0.0);  // always returns 0.7
    const torch::Tensor x = start(64, 1);
    EXPECT_LT((sample_ddpm(diffusion, point, x, seeded_noise(2)) - 0.7).abs().max().item<double>(), 1e-12);
    EXPECT_LT((sample_ddim(s, point, x, 10, 0.0, seeded_noise(2)) - 0.7).abs().max().item<double>(), 1e-12);
    EXPECT_LT((sample_dpmpp_2m(s, point, x, 10) - 0.7).abs().max().item<double>(), 1e-12);
}

TEST(Samplers, GaussianDataHasTheRightMoments) {
    const double mu = 0.5, sd = 0.3;
    const NoiseSchedule s = cosine_schedule(1000);
    const GaussianDiffusion diffusion(s);
    const X0Predictor denoiser = gaussian_denoiser(s, mu, sd);
    const torch::Tensor x = start(40000, 3);
    const Moments ddpm = moments(sample_ddpm(diffusion, denoiser, x, seeded_noise(4)));
    EXPECT_NEAR(ddpm.mean, mu, 0.005);
    EXPECT_NEAR(ddpm.sd / sd, 1.0, 0.02);  // ancestral sampling: exact up to sampling error (0.4 %)
    for (int steps : {10, 50}) {
        const Moments ddim = moments(sample_ddim(s, denoiser, x, steps, 0.0, seeded_noise(5)));
        const Moments dpm = moments(sample_dpmpp_2m(s, denoiser, x, steps));
        std::printf("K = %2d: DDIM sd ratio %.4f, DPM-Solver++ 2M sd ratio %.4f, DDPM (1000) %.4f\n", steps,
                    ddim.sd / sd, dpm.sd / sd, ddpm.sd / sd);
        EXPECT_NEAR(ddim.mean, mu, 0.005);
        EXPECT_NEAR(dpm.mean, mu, 0.005);
        // Discretisation error of each scheme (computed analytically for this problem: see samplers.hpp).
        EXPECT_NEAR(dpm.sd / sd, steps == 10 ? 1.087 : 1.002, 0.01);
        EXPECT_NEAR(ddim.sd / sd, steps == 10 ? 0.855 : 0.971, 0.01);
    }
    // eta = 1 turns DDIM into a stochastic sampler that still matches the data.
    const Moments noisy = moments(sample_ddim(s, denoiser, x, 100, 1.0, seeded_noise(6)));
    EXPECT_NEAR(noisy.sd / sd, 1.0, 0.05);  // measured 0.967: discretisation at K = 100
}

TEST(Samplers, TimestepsFromAnIntermediateStep) {
    EXPECT_EQ(sampling_timesteps(1000, 5, 499), (std::vector<int>{499, 281, 125, 31, 0}));  // 499 (1 - k/4)^2
    EXPECT_EQ(sampling_timesteps(1000, 3, 2), (std::vector<int>{2, 1, 0}));
    EXPECT_THROW(sampling_timesteps(1000, 4, 2), Error);  // more evaluations than steps left
    EXPECT_THROW(sampling_timesteps(10, 1, 10), Error);   // beyond the schedule
}

// SDEdit (the hybrid source) on Gaussian data N(mu, s^2): a start point x_s noised to step t, x_t = sqrt(a) x_s +
// sqrt(1 - a) eps, and ancestral sampling with the exact denoiser from t, draws x0 | x_t. Averaged over eps that
// is a normal distribution with mean mu + k (x_s - mu), k = a s^2 / (a s^2 + 1 - a), and variance
// s^2 (1 - a) / (a s^2 + 1 - a) + a s^4 (1 - a) / (a s^2 + 1 - a)^2: the start is kept in proportion k.
TEST(Samplers, FromAPartlyNoisedStartTheExactPosteriorIsDrawn) {
    const double mu = 0.5, sd = 0.3, x_s = 1.5;
    const NoiseSchedule s = cosine_schedule(1000);
    const GaussianDiffusion diffusion(s);
    const X0Predictor denoiser = gaussian_denoiser(s, mu, sd);
    for (int t : {150, 400}) {
        const double a = s.alphas_cumprod[static_cast<size_t>(t)], v = a * sd * sd + 1 - a;
        const double k = a * sd * sd / v;
        const double expected_sd = std::sqrt(sd * sd * (1 - a) / v + a * sd * sd * sd * sd * (1 - a) / (v * v));
        const torch::Tensor x_t = std::sqrt(a) * x_s + std::sqrt(1 - a) * start(40000, 7);
        const Moments m = moments(sample_ddpm(diffusion, denoiser, x_t, seeded_noise(8), t));
        EXPECT_NEAR(m.mean, mu + k * (x_s - mu), 0.005) << "t = " << t;
        EXPECT_NEAR(m.sd / expected_sd, 1.0, 0.03) << "t = " << t;
    }
    EXPECT_THROW(sample_ddpm(diffusion, denoiser, start(4, 1), seeded_noise(1), 1000), Error);
}
