// The Motion Diffusion Model denoiser (Tevet et al. 2022), `trans_enc` architecture, as the official code
// (GuyTevet/motion-diffusion-model @ d4fd88c) builds it, with the official module names so that weights move
// between PyTorch and t2imu by name:
//   input_process.poseEmbedding   Linear 263 -> d on each frame
//   embed_timestep.time_embed     pe[t] -> Linear -> SiLU -> Linear
//   embed_text                    Linear text_dim -> d (the unconditional pass zeroes the text before it)
//   sequence_pos_encoder          sinusoidal positions (the same table serves the timesteps)
//   seqTransEncoder               post-norm Transformer encoder, GELU (nn/transformer_encoder.hpp)
//   output_process.poseFinal      Linear d -> 263, on every frame but the condition token
// The condition token (time + text) is prepended at position 0. Motions use the official layout
// [batch, 263, 1, frames]; text embeddings are [batch, text_dim].
#pragma once
#include <torch/torch.h>

#include <string>

#include "nn/transformer_encoder.hpp"

namespace t2imu {

struct MdmConfig {
    int64_t njoints = 263;
    int64_t latent_dim = 512;
    int64_t ff_size = 1024;
    int64_t num_layers = 8;
    int64_t num_heads = 4;
    double dropout = 0.1;
    int64_t text_dim = 512;
    int64_t max_len = 5000;    // positional table length
    bool mask_frames = false;  // official flag: padded frames are masked out of attention (needs lengths)
};

MdmConfig read_mdm_config(const std::string& json_path);  // the official args.json keys

class MdmImpl : public torch::nn::Module {
public:
    explicit MdmImpl(const MdmConfig& config);

    // x [B, 263, 1, F], timesteps [B] int64, text [B, text_dim] -> x0 estimate [B, 263, 1, F].
    // uncond: zero the text feature (classifier-free guidance's unconditional pass). lengths [B] (optional, an
    // undefined tensor for none): with mask_frames, frames at or beyond a sample's length are hidden from
    // attention, so they cannot change the valid frames' output.
    torch::Tensor forward(const torch::Tensor& x, const torch::Tensor& timesteps, const torch::Tensor& text,
                          bool uncond = false, const torch::Tensor& lengths = {});
    // uncond + scale * (cond - uncond), computed as one batched forward over both passes.
    torch::Tensor forward_guided(const torch::Tensor& x, const torch::Tensor& timesteps, const torch::Tensor& text,
                                 double scale, const torch::Tensor& lengths = {});

    const MdmConfig& config() const { return config_; }

private:
    MdmConfig config_;
    torch::Tensor pe_;  // [max_len, 1, d], a fixed buffer (not saved, as official checkpoints omit it)
    torch::nn::Linear pose_embedding_{nullptr}, embed_text_{nullptr}, pose_final_{nullptr};
    torch::nn::Sequential time_embed_{nullptr};
    TransformerEncoder encoder_{nullptr};
};
TORCH_MODULE(Mdm);

// Loads safetensors weights by official name; refuses missing, unexpected and mis-shaped keys, naming the key
// and both shapes. Keys under a non-empty `other_prefix` belong to another module stored in the same file (an
// MDM state dict that kept its frozen CLIP: "clip_model.", read by load_clip_text_weights) and are skipped.
void load_mdm_weights(Mdm& model, const std::string& safetensors_path, const std::string& other_prefix = "");

}  // namespace t2imu
