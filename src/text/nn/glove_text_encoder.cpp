#include "text/nn/glove_text_encoder.hpp"

#include <cmath>

#include "text/word_tokenizer.hpp"

namespace t2imu {

GloveTextEncoderImpl::GloveTextEncoderImpl(const WordVectors& vectors, const GloveEncoderConfig& config)
    : vectors_(vectors), config_(config) {
    const int64_t V = vectors.size(), D = WordVectors::kDims;
    glove_ = register_buffer("glove",
                             torch::from_blob(const_cast<float*>(vectors.vector(0)), {V, D}, torch::kFloat32).clone());
    unknown_ = register_parameter("unknown", torch::zeros({D}));
    project_in_ = register_module("project_in", torch::nn::Linear(D, config.model_dim));
    project_out_ = register_module("project_out", torch::nn::Linear(config.model_dim, config.out_dim));
    auto layer =
        torch::nn::TransformerEncoderLayer(torch::nn::TransformerEncoderLayerOptions(config.model_dim, config.heads)
                                               .dim_feedforward(config.ff_size)
                                               .dropout(config.dropout)
                                               .activation(torch::kGELU));
    encoder_ = register_module(
        "encoder", torch::nn::TransformerEncoder(torch::nn::TransformerEncoderOptions(layer, config.layers)));
    // Sinusoidal positions (Vaswani et al.): sin on even, cos on odd channels.
    pe_ = torch::zeros({GloveEncoderConfig::kMaxWords, config.model_dim});
    for (int64_t p = 0; p < GloveEncoderConfig::kMaxWords; ++p)
        for (int64_t i = 0; i < config.model_dim; i += 2) {
            const double angle = static_cast<double>(p) /
                                 std::pow(10000.0, static_cast<double>(i) / static_cast<double>(config.model_dim));
            pe_[p][i] = std::sin(angle);
            if (i + 1 < config.model_dim) pe_[p][i + 1] = std::cos(angle);
        }
    pe_ = register_buffer("pe", pe_);
}

torch::Tensor GloveTextEncoderImpl::forward(const std::vector<std::vector<int>>& captions) {
    const int64_t B = static_cast<int64_t>(captions.size()), L = GloveEncoderConfig::kMaxWords;
    torch::Tensor index = torch::zeros({B, L}, torch::kInt64), unknown = torch::zeros({B, L, 1}),
                  valid = torch::zeros({B, L});
    for (int64_t b = 0; b < B; ++b) {
        const std::vector<int>& c = captions[static_cast<size_t>(b)];
        for (int64_t k = 0; k < std::min<int64_t>(L, static_cast<int64_t>(c.size())); ++k) {
            valid[b][k] = 1;
            if (c[static_cast<size_t>(k)] < 0)
                unknown[b][k][0] = 1;
            else
                index[b][k] = c[static_cast<size_t>(k)];
        }
    }
    const torch::Device device = glove_.device();
    index = index.to(device);
    unknown = unknown.to(device);
    valid = valid.to(device);
    const torch::Tensor words = glove_.index_select(0, index.flatten()).view({B, L, WordVectors::kDims});
    torch::Tensor h = words * (1 - unknown) + unknown * unknown_;  // [B, L, 100]
    h = project_in_->forward(h) + pe_.unsqueeze(0);                // [B, L, d]
    const torch::Tensor padding = valid.eq(0);                     // true = ignore
    // An empty caption would mask every key; give it one visible (zero) slot so attention stays defined.
    torch::Tensor empty = torch::zeros({B, L}, torch::kBool);
    for (int64_t b = 0; b < B; ++b)
        if (captions[static_cast<size_t>(b)].empty()) empty[b][0] = true;
    const torch::Tensor mask = padding & ~empty.to(device);
    h = encoder_->forward(h.transpose(0, 1), {}, mask).transpose(0, 1);  // [B, L, d]
    const torch::Tensor weight = valid.unsqueeze(2);
    const torch::Tensor pooled = (h * weight).sum(1) / weight.sum(1).clamp_min(1.0);
    return project_out_->forward(pooled) * (valid.sum(1, true) > 0).to(torch::kFloat32);
}

torch::Tensor GloveTextEncoderImpl::encode(const std::vector<std::string>& captions) {
    std::vector<std::vector<int>> tokens;
    for (const std::string& c : captions) tokens.push_back(word_indices(c, vectors_));
    return forward(tokens);
}

}  // namespace t2imu
