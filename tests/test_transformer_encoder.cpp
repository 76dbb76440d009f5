// Our post-norm Transformer encoder (nn/transformer_encoder.hpp) against libtorch's module: the same weights
// from the same seed, the same training forward (dropout masks included) and gradients, the fused inference
// path equal to the plain one, and a bf16 forward with padded keys.
#include <gtest/gtest.h>

#include "nn/autocast.hpp"
#include "nn/transformer_encoder.hpp"

using namespace t2imu;

namespace {

EncoderOptions small_options() {
    EncoderOptions o;
    o.d_model = 32;
    o.nhead = 4;
    o.dim_feedforward = 48;
    o.num_layers = 3;
    o.dropout = 0.1;
    return o;
}

torch::nn::TransformerEncoder libtorch_encoder(const EncoderOptions& o) {
    auto layer = torch::nn::TransformerEncoderLayer(torch::nn::TransformerEncoderLayerOptions(o.d_model, o.nhead)
                                                        .dim_feedforward(o.dim_feedforward)
                                                        .dropout(o.dropout)
                                                        .activation(torch::kGELU));
    return torch::nn::TransformerEncoder(torch::nn::TransformerEncoderOptions(layer, o.num_layers));
}

double relative_gap(const torch::Tensor& a, const torch::Tensor& b) {
    return (a - b).abs().max().item<double>() / b.abs().max().item<double>();
}

// [B, S] true on the keys past each length.
torch::Tensor key_padding(const std::vector<int64_t>& lengths, int64_t s) {
    return torch::arange(s).unsqueeze(0) >= torch::tensor(lengths).unsqueeze(1);
}

}  // namespace

TEST(TransformerEncoder, StartsFromLibtorchsWeightsByName) {
    torch::manual_seed(11);
    auto reference = libtorch_encoder(small_options());
    torch::manual_seed(11);
    TransformerEncoder ours(small_options());
    const auto theirs = reference->named_parameters();
    ASSERT_EQ(ours->named_parameters().size(), theirs.size());
    for (const auto& p : ours->named_parameters()) {
        ASSERT_TRUE(theirs.contains(p.key())) << p.key();
        EXPECT_TRUE(torch::equal(p.value(), theirs[p.key()])) << p.key();
    }
}

TEST(TransformerEncoder, TrainingForwardAndGradientsMatchLibtorchWithPaddedKeys) {
    EncoderOptions o = small_options();
    o.dropout = 0;  // the masks come from different generators (nn/dropout.hpp)
    torch::manual_seed(5);
    auto reference = libtorch_encoder(o);
    torch::manual_seed(5);
    TransformerEncoder ours(o);
    const torch::Tensor x = torch::randn({9, 3, 32}), padding = key_padding({9, 6, 2}, 9);
    const torch::Tensor a = reference->forward(x, {}, padding), b = ours->forward(x, padding);
    EXPECT_LT(relative_gap(b, a), 1e-5);
    a.pow(2).sum().backward();
    b.pow(2).sum().backward();
    const auto theirs = reference->named_parameters();
    for (const auto& p : ours->named_parameters())
        EXPECT_LT(relative_gap(p.value().grad(), theirs[p.key()].grad()), 1e-4) << p.key();
}

TEST(TransformerEncoder, FusedInferenceEqualsThePlainPathOnValidFrames) {
    torch::manual_seed(2);
    TransformerEncoder ours(small_options());
    ours->eval();
    const torch::Tensor x = torch::randn({11, 3, 32});
    const std::vector<int64_t> lengths = {11, 7, 3};
    const torch::Tensor padding = key_padding(lengths, 11);
    const torch::Tensor plain = ours->forward(x, padding),
                        plain_unmasked = ours->forward(x);  // gradients on: the plain path
    torch::NoGradGuard no_grad;
    const torch::Tensor fused = ours->forward(x, padding);
    EXPECT_LT(relative_gap(ours->forward(x), plain_unmasked), 1e-5);
    for (int64_t b = 0; b < 3; ++b) {
        const auto valid = torch::indexing::Slice(0, lengths[static_cast<size_t>(b)]);
        EXPECT_LT(relative_gap(fused.index({valid, b}), plain.index({valid, b})), 1e-5) << "sample " << b;
    }
}

TEST(TransformerEncoder, Bf16ForwardWithPaddedKeysStaysCloseToFp32) {
    torch::manual_seed(4);
    TransformerEncoder ours(small_options());
    ours->eval();
    const torch::Tensor x = torch::randn({10, 2, 32}), padding = key_padding({10, 4}, 10);
    const torch::Tensor fp32 = ours->forward(x, padding);
    torch::Tensor bf16;
    {
        const AutocastScope mixed(torch::Device(torch::kCPU), Precision::kBFloat16);
        bf16 = ours->forward(x, padding);
    }
    EXPECT_EQ(bf16.scalar_type(), torch::kFloat32);  // the residual stream and the norms stay fp32
    // Three layers of 8-bit-mantissa products on unit-scale activations: within 5 % of the largest value.
    EXPECT_LT(relative_gap(bf16.slice(0, 0, 4), fp32.slice(0, 0, 4)), 0.05);
    EXPECT_GT(relative_gap(bf16, fp32), 0.0);  // the products did run in bf16
}
