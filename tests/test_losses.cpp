// Loss arithmetic against the official training_losses vectors, and L_acc against a hand-computed case.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include "core/npy.hpp"
#include "diffusion/losses.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

torch::Tensor tensor_of(const std::string& relative) {
    const NdArray a = read_npy(test::shared_path(relative));
    std::vector<float> v = a.to<float>();
    return torch::from_blob(v.data(), a.shape, torch::kFloat).clone();
}

}  // namespace

TEST(Losses, MatchOfficialMaskedL2AndVelocity) {
    std::string x;
    SHARED_OR_SKIP(x, "reference/mdm/training_losses/x_start.npy");
    // Official layout [B, 263, 1, F] -> ours [B, F, 263].
    const torch::Tensor x0 = tensor_of("reference/mdm/training_losses/x_start.npy").squeeze(2).permute({0, 2, 1});
    const torch::Tensor out = tensor_of("reference/mdm/training_losses/model_output.npy").squeeze(2).permute({0, 2, 1});
    const NdArray lengths_npy = read_npy(test::shared_path("reference/mdm/training_losses/lengths.npy"));
    const torch::Tensor lengths = torch::tensor(lengths_npy.to<int64_t>());
    const torch::Tensor mask = frame_mask(lengths, x0.size(1));
    const torch::Tensor rot = masked_mse(x0, out, mask), vel = velocity_mse(x0, out, mask);
    const torch::Tensor rot_ref = tensor_of("reference/mdm/training_losses/lambda_vel1_rot_mse.npy");
    const torch::Tensor vel_ref = tensor_of("reference/mdm/training_losses/lambda_vel1_vel_mse.npy");
    EXPECT_LT((rot - rot_ref).abs().max().item<float>(), 1e-5);
    EXPECT_LT((vel - vel_ref).abs().max().item<float>(), 1e-5);
    EXPECT_NEAR(rot[0].item<float>(), 1.574627161026001f, 1e-5);
}

TEST(Losses, AccelerationLossByHand) {
    // One sample, 5 frames of which 4 are valid, 2 channels. Target: a parabola in channel 0 (second difference
    // 2 everywhere); prediction: zeros. Valid second differences: i = 1, 2 (frames 0..3) -> 2 terms of 2^2 = 4
    // in channel 0 and 0 in channel 1, the mean over N - 2 = 2 differences and 2 channels: 8 / 4.
    torch::Tensor target = torch::zeros({1, 5, 2});
    for (int f = 0; f < 5; ++f) target[0][f][0] = static_cast<float>(f * f);
    const torch::Tensor mask = frame_mask(torch::tensor({int64_t{4}}), 5);
    const torch::Tensor l = acceleration_loss(target, torch::zeros_like(target), mask);
    EXPECT_NEAR(l[0].item<float>(), 2.0f, 1e-6);
    // A prediction with the same second differences (any added line) costs nothing.
    torch::Tensor shifted = target.clone();
    for (int f = 0; f < 5; ++f) shifted[0][f][1] = 0.5f * static_cast<float>(f) + 1.0f;
    shifted.index_put_({0, torch::indexing::Slice(), 0}, target.index({0, torch::indexing::Slice(), 0}) + 3.0f);
    EXPECT_NEAR(acceleration_loss(target, shifted, mask)[0].item<float>(), 0.0f, 1e-6);
    // Gradients flow to the prediction.
    torch::Tensor p = torch::zeros_like(target).requires_grad_(true);
    acceleration_loss(target, p, mask).sum().backward();
    EXPECT_GT(p.grad().abs().sum().item<float>(), 0.0f);
}
