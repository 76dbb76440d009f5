#include "diffusion/gaussian_diffusion.hpp"

#include "core/error.hpp"

namespace t2imu {

GaussianDiffusion::GaussianDiffusion(const NoiseSchedule& schedule) : schedule_(schedule) {}

torch::Tensor GaussianDiffusion::gather(const std::vector<double>& values, const torch::Tensor& t,
                                        const torch::Tensor& like) const {
    if (t.dim() != 1 || t.size(0) != like.size(0))
        throw Error("diffusion", "t", "one step per sample [" + std::to_string(like.size(0)) + "]");
    if (t.min().item<int64_t>() < 0 || t.max().item<int64_t>() >= schedule_.steps)
        throw Error("diffusion", "t", "steps in [0, " + std::to_string(schedule_.steps) + ")");
    // Schedules are float64; as in the official _extract_into_tensor, the value is taken in float64 and then
    // cast to the motion's dtype.
    const torch::Tensor table = torch::tensor(values, torch::TensorOptions().dtype(torch::kDouble));
    std::vector<int64_t> shape(static_cast<size_t>(like.dim()), 1);
    shape[0] = like.size(0);
    return table.index_select(0, t.to(torch::kCPU).to(torch::kLong)).to(like.options()).reshape(shape);
}

torch::Tensor GaussianDiffusion::q_sample(const torch::Tensor& x0, const torch::Tensor& t,
                                          const torch::Tensor& noise) const {
    return gather(schedule_.sqrt_alphas_cumprod, t, x0) * x0 +
           gather(schedule_.sqrt_one_minus_alphas_cumprod, t, x0) * noise;
}

torch::Tensor GaussianDiffusion::posterior_mean(const torch::Tensor& x0, const torch::Tensor& x_t,
                                                const torch::Tensor& t) const {
    return gather(schedule_.posterior_mean_coef1, t, x_t) * x0 + gather(schedule_.posterior_mean_coef2, t, x_t) * x_t;
}

torch::Tensor GaussianDiffusion::p_sample_step(const torch::Tensor& x_t, const torch::Tensor& x0_pred,
                                               const torch::Tensor& t, const torch::Tensor& noise) const {
    const torch::Tensor mean = posterior_mean(x0_pred, x_t, t);
    const torch::Tensor sigma = (0.5 * gather(schedule_.posterior_log_variance_clipped, t, x_t)).exp();
    std::vector<int64_t> shape(static_cast<size_t>(x_t.dim()), 1);
    shape[0] = x_t.size(0);
    const torch::Tensor nonzero = (t != 0).to(x_t.dtype()).to(x_t.device()).reshape(shape);
    return mean + nonzero * sigma * noise;
}

}  // namespace t2imu
