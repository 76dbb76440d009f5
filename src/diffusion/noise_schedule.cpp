#include "diffusion/noise_schedule.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace t2imu {

NoiseSchedule schedule_from_betas(const std::vector<double>& betas) {
    const size_t n = betas.size();
    if (n < 2) throw Error("noise schedule", "steps", "at least 2", std::to_string(n));
    NoiseSchedule s;
    s.steps = static_cast<int>(n);
    s.betas = betas;
    double cumprod = 1.0;
    for (size_t i = 0; i < n; ++i) {
        if (!(betas[i] > 0 && betas[i] <= 1))
            throw Error("noise schedule", "beta " + std::to_string(i), "a value in (0, 1]");
        s.alphas_cumprod_prev.push_back(cumprod);
        cumprod *= 1.0 - betas[i];
        s.alphas_cumprod.push_back(cumprod);
    }
    for (size_t i = 0; i < n; ++i) {
        const double ac = s.alphas_cumprod[i], prev = s.alphas_cumprod_prev[i];
        s.alphas_cumprod_next.push_back(i + 1 < n ? s.alphas_cumprod[i + 1] : 0.0);
        s.sqrt_alphas_cumprod.push_back(std::sqrt(ac));
        s.sqrt_one_minus_alphas_cumprod.push_back(std::sqrt(1.0 - ac));
        s.log_one_minus_alphas_cumprod.push_back(std::log(1.0 - ac));
        s.sqrt_recip_alphas_cumprod.push_back(std::sqrt(1.0 / ac));
        s.sqrt_recipm1_alphas_cumprod.push_back(std::sqrt(1.0 / ac - 1.0));
        s.posterior_variance.push_back(betas[i] * (1.0 - prev) / (1.0 - ac));
        s.posterior_mean_coef1.push_back(betas[i] * std::sqrt(prev) / (1.0 - ac));
        s.posterior_mean_coef2.push_back((1.0 - prev) * std::sqrt(1.0 - betas[i]) / (1.0 - ac));
    }
    // The variance at t = 0 is 0; its log is clipped by taking the value at t = 1 instead.
    for (size_t i = 0; i < n; ++i)
        s.posterior_log_variance_clipped.push_back(std::log(s.posterior_variance[i == 0 ? 1 : i]));
    return s;
}

NoiseSchedule cosine_schedule(int steps) {
    if (steps < 2) throw Error("noise schedule", "steps", "at least 2", std::to_string(steps));
    auto alpha_bar = [](double s) {
        const double c = std::cos((s + 0.008) / 1.008 * M_PI / 2);
        return c * c;
    };
    std::vector<double> raw;
    for (int i = 0; i < steps; ++i)
        raw.push_back(std::min(
            1.0 - alpha_bar(static_cast<double>(i + 1) / steps) / alpha_bar(static_cast<double>(i) / steps), 0.999));
    // SpacedDiffusion's recomputation from the cumulative products.
    const NoiseSchedule base = schedule_from_betas(raw);
    std::vector<double> betas;
    double last = 1.0;
    for (double ac : base.alphas_cumprod) {
        betas.push_back(1.0 - ac / last);
        last = ac;
    }
    return schedule_from_betas(betas);
}

}  // namespace t2imu
