#include <gtest/gtest.h>
#include <torch/torch.h>

#include "core/npy.hpp"
#include "diffusion/recover_from_ric_torch.hpp"
#include "motion/humanml3d.hpp"
#include "test_util.hpp"

using namespace t2imu;

TEST(RecoverFromRicTorch, MatchesTheReferenceAndIsDifferentiable) {
    std::string path;
    SHARED_OR_SKIP(path, "reference/humanml3d/generated/seq_synth_turn/features_263.npy");
    const NdArray a = read_npy(path);
    std::vector<float> v = a.to<float>();
    const torch::Tensor features =
        torch::from_blob(v.data(), {1, a.shape[0], 263}, torch::kFloat).clone().requires_grad_(true);
    const torch::Tensor joints = recover_from_ric_torch(features);
    ASSERT_EQ(joints.sizes(), (std::vector<int64_t>{1, a.shape[0], 22, 3}));
    const std::vector<double> expected =
        read_npy(test::shared_path("reference/humanml3d/generated/seq_synth_turn/recover_from_ric.npy")).to<double>();
    const torch::Tensor flat = joints.detach().reshape({-1}).to(torch::kDouble);
    double worst = 0;
    for (size_t i = 0; i < expected.size(); ++i)
        worst = std::max(worst, std::abs(flat[static_cast<int64_t>(i)].item<double>() - expected[i]));
    EXPECT_LT(worst, 1e-5);
    // A turn of the first frame's yaw rate moves every later root position: the gradient reaches channel 0.
    joints.index({0, -1, 0, 0}).backward();
    EXPECT_NE(features.grad().index({0, 0, 0}).item<float>(), 0.0f);
    EXPECT_EQ(features.grad().index({0, -1, 0}).item<float>(), 0.0f);  // the last frame's velocity is unused
}

TEST(RecoverFromRicTorch, BatchesAgreeWithThePlainImplementation) {
    torch::manual_seed(3);
    const torch::Tensor x = torch::randn({3, 20, 263}, torch::kDouble) * 0.1;
    const torch::Tensor j = recover_from_ric_torch(x);
    for (int64_t b = 0; b < 3; ++b) {
        FeatureMatrix f(20, 263);
        for (int64_t t = 0; t < 20; ++t)
            for (int64_t c = 0; c < 263; ++c) f(t, c) = x[b][t][c].item<double>();
        const JointSequence ref = recover_from_ric(f);
        for (int t = 0; t < 20; ++t)
            for (int k = 0; k < 22; ++k)
                for (int d = 0; d < 3; ++d) ASSERT_NEAR(j[b][t][k][d].item<double>(), ref.at(t, k)[d], 1e-12);
    }
}
