// AutocastScope (nn/autocast.hpp): products in bfloat16 inside the scope, float32 outside; nesting restores.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "nn/autocast.hpp"

using namespace t2imu;

TEST(Autocast, Bf16ScopeRunsProductsInBfloat16AndRestores) {
    const torch::Tensor a = torch::randn({8, 16}), b = torch::randn({16, 4});
    {
        const AutocastScope mixed(torch::Device(torch::kCPU), Precision::kBFloat16);
        const torch::Tensor c = torch::matmul(a, b);
        EXPECT_EQ(c.scalar_type(), torch::kBFloat16);
        // bfloat16 keeps 8 significant bits: the product is within 2^-7 of float32's, relative to its scale.
        EXPECT_LT(
            (c.to(torch::kFloat32) - torch::matmul(a.to(torch::kFloat64), b.to(torch::kFloat64)).to(torch::kFloat32))
                .abs()
                .max()
                .item<double>(),
            torch::matmul(a, b).abs().max().item<double>() / 64);
        {
            const AutocastScope inner(torch::Device(torch::kCPU), Precision::kBFloat16);
            EXPECT_EQ(torch::matmul(a, b).scalar_type(), torch::kBFloat16);
        }
        EXPECT_EQ(torch::matmul(a, b).scalar_type(), torch::kBFloat16);  // the inner scope left the outer one on
    }
    EXPECT_EQ(torch::matmul(a, b).scalar_type(), torch::kFloat32);
}

TEST(Autocast, Fp32ScopeChangesNothing) {
    const AutocastScope plain(torch::Device(torch::kCPU), Precision::kFloat32);
    EXPECT_EQ(torch::matmul(torch::randn({2, 3}), torch::randn({3, 2})).scalar_type(), torch::kFloat32);
}

TEST(Autocast, PrecisionNamesRoundTripAndOthersAreRefusedByField) {
    for (const Precision p : {Precision::kFloat32, Precision::kBFloat16})
        EXPECT_EQ(parse_precision(precision_name(p), "c.toml", "train.precision"), p);
    try {
        parse_precision("fp16", "c.toml", "train.precision");
        FAIL() << "fp16 accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("train.precision"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("c.toml"), std::string::npos) << e.what();
    }
}
