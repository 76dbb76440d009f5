#include "diffusion/lacc_evaluation.hpp"

#include <cstdio>
#include "core/number_text.hpp"

#include "data/hml3d_dataset.hpp"
#include "diffusion/gaussian_diffusion.hpp"
#include "diffusion/losses.hpp"

namespace t2imu {

CsvTable evaluate_lacc(MotionModel& model, const std::string& dataset, const std::string& split, uint64_t seed) {
    torch::NoGradGuard no_grad;
    const Hml3dDataset data(dataset, split);
    const GaussianDiffusion diffusion(model.schedule);
    CsvTable out;
    out.header = {"id", "caption", "t", "l_acc", "l_simple"};
    for (size_t i = 0; i < data.clips().size(); ++i) {
        const MotionClip& clip = data.clips()[i];
        const int64_t frames = std::min<int64_t>(clip.features.rows(), kMaxMotionFrames);
        // Normalised with the model's statistics: the space the model works in.
        std::vector<float> normalised(static_cast<size_t>(frames) * 263);
        for (int64_t f = 0; f < frames; ++f)
            for (int64_t c = 0; c < 263; ++c)
                normalised[static_cast<size_t>(f * 263 + c)] =
                    static_cast<float>((clip.features(f, c) - model.stats.mean[c]) / model.stats.std[c]);
        const torch::Tensor x0 =
            torch::from_blob(normalised.data(), {1, frames, 263}, torch::kFloat32).to(model.device);
        // t and the noise are drawn on the CPU: the same draws on every device.
        torch::Generator gen = at::detail::createCPUGenerator(seed + i);
        const torch::Tensor t = torch::randint(model.schedule.steps, {1}, gen, torch::kInt64).to(model.device);
        const torch::Tensor x0_mdm = x0.permute({0, 2, 1}).unsqueeze(2);
        const torch::Tensor x_t =
            diffusion.q_sample(x0_mdm, t, torch::randn(x0_mdm.sizes(), gen, torch::kFloat32).to(model.device));
        const std::string caption = clip.captions.front().caption;
        const torch::Tensor lengths =
            torch::full({1}, frames, torch::TensorOptions().dtype(torch::kInt64).device(model.device));
        const torch::Tensor x0_hat =
            model.mdm->forward(x_t, t, model.encode_text({caption}), false, lengths).squeeze(2).permute({0, 2, 1});
        const torch::Tensor mask = frame_mask(lengths, frames);
        const std::string acc = general_text(acceleration_loss(x0, x0_hat, mask).item<double>(), 8);
        const std::string simple = general_text(masked_mse(x0, x0_hat, mask).item<double>(), 8);
        out.rows.push_back({clip.id, caption, std::to_string(t.item<int64_t>()), acc, simple});
    }
    return out;
}

}  // namespace t2imu
