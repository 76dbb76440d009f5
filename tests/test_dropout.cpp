// nn/dropout.hpp: the keep rate, independence of neighbouring elements, the scale and gradient, and the
// reproducibility promised (seed -> mask, whatever the thread count).
#include <gtest/gtest.h>

#include "nn/dropout.hpp"
#include "nn/threads.hpp"

using namespace t2imu;

TEST(Dropout, KeepsOneMinusPAndNeighboursAreIndependent) {
    for (const double p : {0.1, 0.5}) {
        const torch::Tensor keep = dropout_keep_mask({1000, 1000}, p, 42).to(torch::kFloat64);
        // 10^6 Bernoulli draws: the rate's standard deviation is at most 0.0005; allow 4 of them.
        EXPECT_NEAR(keep.mean().item<double>(), 1 - p, 0.002) << p;
        // Both of two neighbours dropped (within one hash and across hashes): p^2.
        const torch::Tensor flat = keep.flatten(), dropped = 1 - flat;
        EXPECT_NEAR((dropped.slice(0, 0, -1) * dropped.slice(0, 1)).mean().item<double>(), p * p, 0.003) << p;
        EXPECT_NEAR((dropped.slice(0, 0, -4) * dropped.slice(0, 4)).mean().item<double>(), p * p, 0.003) << p;
    }
}

TEST(Dropout, TheSameSeedGivesTheSameMaskOnAnyThreadCount) {
    const int before = torch_threads();
    set_torch_threads(1);
    const torch::Tensor one = dropout_keep_mask({300, 777}, 0.1, 7);
    set_torch_threads(2);
    const torch::Tensor two = dropout_keep_mask({300, 777}, 0.1, 7);
    set_torch_threads(before);
    EXPECT_TRUE(torch::equal(one, two));
    EXPECT_FALSE(torch::equal(one, dropout_keep_mask({300, 777}, 0.1, 8)));
    // The seed comes from libtorch's default generator: reseeding it repeats the dropout.
    const torch::Tensor x = torch::ones({64, 64});
    torch::manual_seed(3);
    const torch::Tensor a = hashed_dropout(x, 0.2, true);
    torch::manual_seed(3);
    EXPECT_TRUE(torch::equal(a, hashed_dropout(x, 0.2, true)));
}

TEST(Dropout, ScalesKeptElementsAndPassesGradientsThroughThemOnly) {
    torch::manual_seed(1);
    const torch::Tensor x = torch::full({50, 40}, 2.0).requires_grad_(true);
    const torch::Tensor y = hashed_dropout(x, 0.25, true);
    const torch::Tensor kept = y.detach() != 0;
    EXPECT_TRUE(torch::allclose(y.detach().masked_select(kept), torch::full({kept.sum().item<int64_t>()}, 2.0 / 0.75)));
    y.sum().backward();
    EXPECT_TRUE(torch::equal(x.grad(), kept.to(torch::kFloat32) / 0.75));
    EXPECT_TRUE(torch::equal(hashed_dropout(x, 0.25, false), x));  // outside training: the identity
    EXPECT_EQ(hashed_dropout(x.to(torch::kBFloat16), 0.25, true).scalar_type(), torch::kBFloat16);
}
