// A post-norm Transformer encoder (Vaswani et al.; PyTorch's nn.TransformerEncoder with norm_first=False), with
// the parameter names of PyTorch's and libtorch's modules, so official weights load by name:
//   layers.N.self_attn.in_proj_weight [3E, E], in_proj_bias [3E], out_proj.{weight,bias}
//   layers.N.linear1.{weight,bias} [F, E] / [F], linear2 [E, F] / [E], norm1 / norm2 .{weight,bias} [E]
// Each layer: x = norm1(x + dropout(attention(x))); x = norm2(x + dropout(linear2(dropout(act(linear1(x)))))).
//
// Why our own and not torch::nn::TransformerEncoder: (1) mixed precision: libtorch 1.13's C++ attention masks
// padded keys with a masked_fill that has no bfloat16 kernel, so under autocast (nn/autocast.hpp) it throws;
// here the scores take an additive float mask and the softmax runs in float32; (2) inference: PyTorch's module
// takes a fused kernel in eval mode (at::_transformer_encoder_layer_fwd: packed QKV, masked softmax, fused
// bias and activation) that the C++ module never takes; here eval mode without gradients takes it too. The
// training path initialises like the C++ module (tests/test_transformer_encoder.cpp checks it and, without
// dropout, the forward and gradients against libtorch's module); its dropout is nn/dropout.hpp's, in the same
// places (the attention map, after attention, inside and after the feed-forward block).
#pragma once
#include <torch/torch.h>

namespace t2imu {

struct EncoderOptions {
    int64_t d_model = 512, nhead = 4, dim_feedforward = 1024, num_layers = 8;
    double dropout = 0.1, eps = 1e-5;
    bool gelu = true;  // else ReLU
};

class EncoderLayerImpl : public torch::nn::Module {
public:
    explicit EncoderLayerImpl(const EncoderOptions& o);
    // x [S, B, E]; additive_mask [B, 1, 1, S] float (0 or -inf) or undefined.
    torch::Tensor forward(const torch::Tensor& x, const torch::Tensor& additive_mask);
    // The fused inference kernel: x [B, S, E] (batch-first); key_padding [B, S] bool or undefined.
    torch::Tensor forward_fused(const torch::Tensor& x, const torch::Tensor& key_padding);

private:
    torch::Tensor attention(const torch::Tensor& x, const torch::Tensor& additive_mask);
    EncoderOptions o_;
    std::shared_ptr<torch::nn::Module> self_attn_;
    torch::Tensor in_proj_weight_, in_proj_bias_;
    torch::nn::Linear out_proj_{nullptr}, linear1_{nullptr}, linear2_{nullptr};
    torch::nn::LayerNorm norm1_{nullptr}, norm2_{nullptr};
};
TORCH_MODULE(EncoderLayer);

class TransformerEncoderImpl : public torch::nn::Module {
public:
    explicit TransformerEncoderImpl(const EncoderOptions& o);
    // seq [S, B, E]; key_padding [B, S] bool, true where a key must not be attended (a padded frame), or
    // undefined. Returns [S, B, E]. Eval mode with gradients off and float32 input takes the fused kernel.
    torch::Tensor forward(const torch::Tensor& seq, const torch::Tensor& key_padding = {});

private:
    torch::nn::ModuleList layers_{nullptr};
};
TORCH_MODULE(TransformerEncoder);

}  // namespace t2imu
