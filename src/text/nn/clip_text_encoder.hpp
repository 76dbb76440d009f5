// CLIP's text tower (Radford et al. 2021), as MDM uses it frozen for its text condition, for users who hold the
// weights (ViT-B/32: width 512, 8 heads, 12 layers, context 77, vocabulary 49408, 512-d output). Parameters
// carry OpenAI's state-dict names:
//   token_embedding.weight [V, W], positional_embedding [C, W]
//   transformer.resblocks.N.{ln_1, attn.in_proj_weight [3W, W] / in_proj_bias (q, k, v stacked), attn.out_proj,
//                            ln_2, mlp.c_fc [4W, W], mlp.c_proj [W, 4W]}
//   ln_final, text_projection [W, E] (applied as x @ P)
// Each block is pre-LN: x + attn(ln_1(x)) under a causal mask, then x + c_proj(QuickGELU(c_fc(ln_2(x)))),
// QuickGELU(x) = x * sigmoid(1.702 x). The sentence feature is ln_final's output at the end-of-text token (the
// largest id of a row, as CLIP takes it) times text_projection. The causal mask makes everything after that
// token (padding) invisible to it.
//
// MDM's encode_text (humanml/kit): clip.tokenize with context 20 + 2 = 22 and truncation, then zero columns up to
// 77, then encode_text(...).float(). MDM runs CLIP in float16 on a GPU; this runs in float32, so features
// differ from MDM's by float16 rounding (about 1e-3 relative).
#pragma once
#include <torch/torch.h>

#include <memory>
#include <string>
#include <vector>

#include "text/clip_bpe.hpp"

namespace t2imu {

struct ClipTextConfig {
    int64_t vocab_size = 49408, context_length = 77, width = 512, heads = 8, layers = 12, embed_dim = 512;
    int64_t mdm_text_tokens = 22;  // MDM's context for HumanML3D/KIT prompts: 20 words' tokens + SOT + EOT
};

class ClipTextEncoderImpl : public torch::nn::Module {
public:
    explicit ClipTextEncoderImpl(const ClipTextConfig& config);

    // ids [B, L] int64, L <= context_length, each row holding its EOT (the row's largest id) -> [B, embed_dim].
    torch::Tensor forward(const torch::Tensor& ids);
    // ln_final's output [B, L, W] before pooling and projection.
    torch::Tensor hidden_states(const torch::Tensor& ids);
    // MDM's text condition: tokenized with context mdm_text_tokens (truncating), zero-padded to context_length.
    // Needs a tokenizer (set_tokenizer).
    torch::Tensor encode(const std::vector<std::string>& captions);

    // Refuses a tokenizer whose vocabulary is not the token embedding's size.
    void set_tokenizer(std::shared_ptr<const ClipBpeTokenizer> tokenizer);
    const ClipTextConfig& config() const { return config_; }

private:
    struct Block {
        torch::nn::LayerNorm ln_1{nullptr}, ln_2{nullptr};
        torch::Tensor in_proj_weight, in_proj_bias;
        torch::nn::Linear out_proj{nullptr}, c_fc{nullptr}, c_proj{nullptr};
    };
    ClipTextConfig config_;
    torch::nn::Embedding token_embedding_{nullptr};
    torch::Tensor positional_embedding_, text_projection_;
    std::vector<Block> blocks_;
    torch::nn::LayerNorm ln_final_{nullptr};
    std::shared_ptr<const ClipBpeTokenizer> tokenizer_;
};
TORCH_MODULE(ClipTextEncoder);

// Loads the text tower's weights by name from a safetensors file holding, any one of:
//   OpenAI's names (CLIP's model.state_dict(): the image tower's visual.*, logit_scale and the JIT archive's
//     context_length / vocab_size / input_resolution entries are ignored);
//   the same under a prefix such as MDM's "clip_model." (then keys outside the prefix are ignored, so a whole
//     MDM state dict can be given);
//   Hugging Face CLIPModel / CLIPTextModelWithProjection names (text_model.embeddings.token_embedding.weight,
//     text_model.encoder.layers.N.self_attn.{q,k,v,out}_proj, layer_norm1/2, mlp.fc1/fc2,
//     text_model.final_layer_norm, text_projection.weight = P^T); vision_model.*, visual_projection.*,
//     logit_scale and position_ids are ignored.
// Missing, unexpected and mis-shaped tensors are refused with an Error naming the key and both shapes.
void load_clip_text_weights(ClipTextEncoder& model, const std::string& safetensors_path);

// The sizes of the text tower stored in a file of the above kinds (width, layers, heads from width / 64 as
// CLIP builds it, context, vocabulary, output), so a model folder need not repeat them.
ClipTextConfig read_clip_text_config(const std::string& safetensors_path);

}  // namespace t2imu
