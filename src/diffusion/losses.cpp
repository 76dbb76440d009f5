#include "diffusion/losses.hpp"

namespace t2imu {

torch::Tensor frame_mask(const torch::Tensor& lengths, int64_t frames) {
    const torch::Tensor f = torch::arange(frames, torch::TensorOptions().dtype(torch::kInt64).device(lengths.device()));
    return (f.unsqueeze(0) < lengths.unsqueeze(1)).to(torch::kFloat);
}

torch::Tensor masked_mse(const torch::Tensor& target, const torch::Tensor& prediction, const torch::Tensor& mask) {
    const torch::Tensor m = mask.to(target.dtype());
    const torch::Tensor se = (target - prediction).pow(2).sum(-1);  // [B, F]
    return (se * m).sum(1) / (m.sum(1) * static_cast<double>(target.size(-1)) + 1e-8);
}

torch::Tensor velocity_mse(const torch::Tensor& target, const torch::Tensor& prediction, const torch::Tensor& mask) {
    using torch::indexing::Slice;
    auto vel = [](const torch::Tensor& x) {
        const torch::Tensor d = x.index({Slice(), Slice(1, torch::indexing::None)}) - x.index({Slice(), Slice(0, -1)});
        return d.index({"...", Slice(0, -1)});  // drop the last channel
    };
    return masked_mse(vel(target), vel(prediction), mask.index({Slice(), Slice(1, torch::indexing::None)}));
}

torch::Tensor acceleration_loss(const torch::Tensor& target, const torch::Tensor& prediction,
                                const torch::Tensor& mask) {
    using torch::indexing::Slice;
    auto acc = [](const torch::Tensor& x) {
        return x.index({Slice(), Slice(2, torch::indexing::None)}) - 2 * x.index({Slice(), Slice(1, -1)}) +
               x.index({Slice(), Slice(0, -2)});
    };
    const torch::Tensor m = mask.to(target.dtype());
    const torch::Tensor valid = m.index({Slice(), Slice(2, torch::indexing::None)});  // frame i+1 valid
    const torch::Tensor se = (acc(target) - acc(prediction)).pow(2).sum(-1);          // [B, F-2]
    const double channels = static_cast<double>(target.size(-1));
    return (se * valid).sum(1) / ((m.sum(1) - 2).clamp_min(1) * channels);
}

}  // namespace t2imu
