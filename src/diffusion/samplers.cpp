#include "diffusion/samplers.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace t2imu {

namespace {

torch::Tensor step_tensor(int t, const torch::Tensor& x) {
    return torch::full({x.size(0)}, t, torch::TensorOptions().dtype(torch::kInt64).device(x.device()));
}

}  // namespace

std::vector<int> sampling_timesteps(int schedule_steps, int steps, int t_start) {
    const int first = t_start < 0 ? schedule_steps - 1 : t_start;
    if (first >= schedule_steps)
        throw Error("sampler", "start step", "0.." + std::to_string(schedule_steps - 1), std::to_string(first));
    if (steps < 1 || steps > first + 1)
        throw Error("sampler", "steps", "1.." + std::to_string(first + 1), std::to_string(steps));
    if (steps == 1) return {first};
    std::vector<int> ts;
    for (int k = 0; k < steps; ++k) {
        const double u = 1.0 - static_cast<double>(k) / (steps - 1);
        int t = static_cast<int>(std::lround(first * u * u));
        if (!ts.empty()) t = std::min(t, ts.back() - 1);  // distinct steps,
        t = std::max(t, steps - 1 - k);                   // leaving one for each remaining evaluation
        ts.push_back(t);
    }
    return ts;
}

torch::Tensor sample_ddpm(const GaussianDiffusion& diffusion, const X0Predictor& denoiser, torch::Tensor x,
                          const NoiseSource& noise, int t_start) {
    torch::NoGradGuard no_grad;
    if (t_start >= diffusion.steps())
        throw Error("sampler", "start step", "0.." + std::to_string(diffusion.steps() - 1), std::to_string(t_start));
    for (int t = t_start < 0 ? diffusion.steps() - 1 : t_start; t >= 0; --t) {
        const torch::Tensor ts = step_tensor(t, x);
        x = diffusion.p_sample_step(x, denoiser(x, ts), ts, noise(x));
    }
    return x;
}

torch::Tensor sample_ddim(const NoiseSchedule& s, const X0Predictor& denoiser, torch::Tensor x, int steps, double eta,
                          const NoiseSource& noise, int t_start) {
    torch::NoGradGuard no_grad;
    const std::vector<int> ts = sampling_timesteps(s.steps, steps, t_start);
    for (size_t i = 0; i < ts.size(); ++i) {
        const torch::Tensor x0 = denoiser(x, step_tensor(ts[i], x));
        if (i + 1 == ts.size()) return x0;
        const double a = s.alphas_cumprod[static_cast<size_t>(ts[i])],
                     a_next = s.alphas_cumprod[static_cast<size_t>(ts[i + 1])];
        const torch::Tensor eps = (x - std::sqrt(a) * x0) / std::sqrt(1 - a);
        const double sigma = eta * std::sqrt((1 - a_next) / (1 - a)) * std::sqrt(1 - a / a_next);
        x = std::sqrt(a_next) * x0 + std::sqrt(std::max(1 - a_next - sigma * sigma, 0.0)) * eps;
        if (sigma > 0) x = x + sigma * noise(x);
    }
    return x;
}

torch::Tensor sample_dpmpp_2m(const NoiseSchedule& s, const X0Predictor& denoiser, torch::Tensor x, int steps,
                              int t_start) {
    torch::NoGradGuard no_grad;
    const std::vector<int> ts = sampling_timesteps(s.steps, steps, t_start);
    const auto alpha = [&](int t) { return std::sqrt(s.alphas_cumprod[static_cast<size_t>(t)]); };
    const auto sigma = [&](int t) { return std::sqrt(1 - s.alphas_cumprod[static_cast<size_t>(t)]); };
    const auto lambda = [&](int t) { return std::log(alpha(t) / sigma(t)); };
    torch::Tensor previous_x0;
    double previous_h = 0;
    for (size_t i = 0; i < ts.size(); ++i) {
        const torch::Tensor x0 = denoiser(x, step_tensor(ts[i], x));
        if (i + 1 == ts.size()) return x0;
        const int t = ts[i], t_next = ts[i + 1];
        const double h = lambda(t_next) - lambda(t);
        torch::Tensor d = x0;
        if (previous_x0.defined()) {
            const double r = previous_h / h;
            d = (1 + 1 / (2 * r)) * x0 - (1 / (2 * r)) * previous_x0;
        }
        x = (sigma(t_next) / sigma(t)) * x - alpha(t_next) * std::expm1(-h) * d;
        previous_x0 = x0;
        previous_h = h;
    }
    return x;
}

}  // namespace t2imu
