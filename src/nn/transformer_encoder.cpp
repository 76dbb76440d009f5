#include "nn/transformer_encoder.hpp"

#include <cmath>
#include <limits>

#include "nn/dropout.hpp"

namespace t2imu {

namespace F = torch::nn::functional;

EncoderLayerImpl::EncoderLayerImpl(const EncoderOptions& o) : o_(o) {
    // A container named self_attn holding the packed projection and out_proj, as in PyTorch's MultiheadAttention.
    // Initialised in libtorch's order of random draws (out_proj's Linear, then Xavier on the packed projection),
    // so a seeded model starts from the weights libtorch's module would have.
    self_attn_ = register_module("self_attn", std::make_shared<torch::nn::Module>());
    in_proj_weight_ = self_attn_->register_parameter("in_proj_weight", torch::empty({3 * o.d_model, o.d_model}));
    in_proj_bias_ = self_attn_->register_parameter("in_proj_bias", torch::zeros({3 * o.d_model}));
    out_proj_ = self_attn_->register_module("out_proj", torch::nn::Linear(o.d_model, o.d_model));
    {
        torch::NoGradGuard no_grad;
        torch::nn::init::xavier_uniform_(in_proj_weight_);
        out_proj_->bias.zero_();
    }
    linear1_ = register_module("linear1", torch::nn::Linear(o.d_model, o.dim_feedforward));
    linear2_ = register_module("linear2", torch::nn::Linear(o.dim_feedforward, o.d_model));
    norm1_ = register_module("norm1", torch::nn::LayerNorm(torch::nn::LayerNormOptions({o.d_model}).eps(o.eps)));
    norm2_ = register_module("norm2", torch::nn::LayerNorm(torch::nn::LayerNormOptions({o.d_model}).eps(o.eps)));
}

torch::Tensor EncoderLayerImpl::attention(const torch::Tensor& x, const torch::Tensor& additive_mask) {
    const int64_t s = x.size(0), b = x.size(1), h = o_.nhead, hd = o_.d_model / o_.nhead;
    const std::vector<torch::Tensor> qkv = F::linear(x, in_proj_weight_, in_proj_bias_).chunk(3, -1);
    // [S, B, E] -> [B * H, S, hd], the query scaled by 1 / sqrt(hd) before the product (as PyTorch does).
    const auto heads = [&](const torch::Tensor& t) { return t.contiguous().view({s, b * h, hd}).transpose(0, 1); };
    const torch::Tensor q = heads(qkv[0] * (1.0 / std::sqrt(static_cast<double>(hd)))), k = heads(qkv[1]),
                        v = heads(qkv[2]);
    torch::Tensor weights = torch::bmm(q, k.transpose(1, 2));  // [B * H, S, S]: bf16 under autocast, else fp32
    {
        // The map stays in the products' precision: the softmax accumulates in fp32 internally, and its output
        // would be rounded to bf16 for the next product anyway. Kept out of autocast's fp32 list on purpose: an
        // fp32 copy of a batch-64 map is 40 MB, above glibc's largest reusable block (a fresh mmap each time).
        const c10::impl::ExcludeDispatchKeyGuard keep_dtype(c10::DispatchKey::AutocastCPU);
        if (additive_mask.defined())
            weights = (weights.view({b, h, s, s}) + additive_mask.to(weights.scalar_type())).view({b * h, s, s});
        weights = torch::softmax(weights, -1);
    }
    weights = hashed_dropout(weights, o_.dropout, is_training());
    const torch::Tensor out = torch::bmm(weights, v).transpose(0, 1).contiguous().view({s, b, o_.d_model});
    return out_proj_->forward(out);
}

torch::Tensor EncoderLayerImpl::forward(const torch::Tensor& x, const torch::Tensor& additive_mask) {
    const auto drop = [&](const torch::Tensor& t) { return hashed_dropout(t, o_.dropout, is_training()); };
    // The residual stream stays fp32: under autocast the products return bf16 and are widened on adding.
    torch::Tensor y = norm1_->forward(x + drop(attention(x, additive_mask)).to(x.scalar_type()));
    torch::Tensor hidden = linear1_->forward(y);
    hidden = o_.gelu ? F::gelu(hidden) : F::relu(hidden);
    return norm2_->forward(y + drop(linear2_->forward(drop(hidden))).to(y.scalar_type()));
}

torch::Tensor EncoderLayerImpl::forward_fused(const torch::Tensor& x, const torch::Tensor& key_padding) {
    const c10::optional<torch::Tensor> mask =
        key_padding.defined() ? c10::optional<torch::Tensor>(key_padding) : c10::nullopt;
    const c10::optional<int64_t> mask_type =
        key_padding.defined() ? c10::optional<int64_t>(1) : c10::nullopt;  // 1: key padding
    return at::_transformer_encoder_layer_fwd(
        x, o_.d_model, o_.nhead, in_proj_weight_, in_proj_bias_, out_proj_->weight, out_proj_->bias, o_.gelu,
        /*norm_first=*/false, o_.eps, norm1_->weight, norm1_->bias, norm2_->weight, norm2_->bias, linear1_->weight,
        linear1_->bias, linear2_->weight, linear2_->bias, mask, mask_type);
}

TransformerEncoderImpl::TransformerEncoderImpl(const EncoderOptions& o) {
    // As in PyTorch's and libtorch's encoders, every layer starts as a copy of the first one's initialisation
    // (theirs deep-copies one prototype layer), so a seeded model starts from the weights theirs would have.
    layers_ = register_module("layers", torch::nn::ModuleList());
    const EncoderLayer first(o);
    layers_->push_back(first);
    for (int64_t i = 1; i < o.num_layers; ++i) {
        const EncoderLayer copy(o);
        torch::NoGradGuard no_grad;
        const auto source = first->parameters();
        const auto target = copy->parameters();
        for (size_t p = 0; p < source.size(); ++p) target[p].copy_(source[p]);
        layers_->push_back(copy);
    }
}

torch::Tensor TransformerEncoderImpl::forward(const torch::Tensor& seq, const torch::Tensor& key_padding) {
    const bool fused = !is_training() && !torch::GradMode::is_enabled() && seq.scalar_type() == torch::kFloat32 &&
                       (seq.device().is_cpu() || seq.device().is_cuda());
    if (fused) {
        torch::Tensor x = seq.transpose(0, 1).contiguous();  // the fused kernel is batch-first
        for (const auto& layer : *layers_) x = layer->as<EncoderLayerImpl>()->forward_fused(x, key_padding);
        return x.transpose(0, 1);
    }
    torch::Tensor additive;  // [B, 1, 1, S]: 0 where attended, -inf on padded keys
    if (key_padding.defined())
        additive = torch::zeros(key_padding.sizes(), seq.options().dtype(torch::kFloat32))
                       .masked_fill(key_padding, -std::numeric_limits<float>::infinity())
                       .view({key_padding.size(0), 1, 1, key_padding.size(1)});
    torch::Tensor x = seq;
    for (const auto& layer : *layers_) x = layer->as<EncoderLayerImpl>()->forward(x, additive);
    return x;
}

}  // namespace t2imu
