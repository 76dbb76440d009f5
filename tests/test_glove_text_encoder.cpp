// The default (GloVe + transformer) text encoder: shapes, masking, unknown words, what trains and what not.
#include <gtest/gtest.h>

#include "text/nn/glove_text_encoder.hpp"

using namespace t2imu;

namespace {
WordVectors small_vocabulary() {
    const std::vector<std::string> words = {"a", "person", "walks", "runs", "slowly", "forward", "."};
    std::vector<float> v(words.size() * 100);
    for (size_t i = 0; i < v.size(); ++i) v[i] = static_cast<float>(std::sin(0.7 * static_cast<double>(i)));
    return WordVectors(words, v);
}
}  // namespace

TEST(GloveTextEncoder, ShapesMaskingAndUnknownWords) {
    torch::manual_seed(0);
    const WordVectors vocab = small_vocabulary();
    GloveTextEncoder enc(vocab, GloveEncoderConfig{});
    enc->eval();  // no dropout: outputs are deterministic
    torch::NoGradGuard no_grad;
    const torch::Tensor alone = enc->encode({"a person walks slowly"});
    EXPECT_EQ(alone.sizes(), (std::vector<int64_t>{1, 512}));
    // The same caption beside a longer one: padding must not leak into it.
    const torch::Tensor batched =
        enc->encode({"a person walks slowly", "a person runs forward slowly . a person walks"});
    EXPECT_LT((batched[0] - alone[0]).abs().max().item<double>(), 1e-5);
    EXPECT_GT((batched[1] - batched[0]).abs().max().item<double>(), 1e-3);  // different captions differ
    // Word order matters (positions), and two unknown words are the same <unk>.
    EXPECT_GT((enc->encode({"person walks"})[0] - enc->encode({"walks person"})[0]).abs().max().item<double>(), 1e-4);
    EXPECT_LT((enc->encode({"a zzz walks"})[0] - enc->encode({"a qqq walks"})[0]).abs().max().item<double>(), 1e-6);
    EXPECT_EQ(enc->encode({""}).abs().max().item<double>(), 0.0);  // the unconditional (zero) text
}

TEST(GloveTextEncoder, WordVectorsStayFixedTheRestTrains) {
    torch::manual_seed(1);
    const WordVectors vocab = small_vocabulary();
    GloveTextEncoder enc(vocab, GloveEncoderConfig{});
    for (const auto& p : enc->named_parameters()) EXPECT_EQ(p.key().find("glove"), std::string::npos) << p.key();
    enc->encode({"a person walks", "zzz runs"}).pow(2).sum().backward();
    int with_grad = 0;
    for (const auto& p : enc->named_parameters())
        if (p.value().grad().defined() && p.value().grad().abs().sum().item<double>() > 0) ++with_grad;
    EXPECT_EQ(with_grad, static_cast<int>(enc->parameters().size()));  // <unk>, projections and every layer
}
