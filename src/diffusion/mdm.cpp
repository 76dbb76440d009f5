#include "diffusion/mdm.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "nn/dropout.hpp"
#include "nn/state_dict.hpp"

namespace t2imu {

namespace {

// pe[pos, 2i] = sin(pos w_i), pe[pos, 2i+1] = cos(pos w_i), w_i = 10000^(-2i/d).
torch::Tensor sinusoidal_table(int64_t max_len, int64_t d) {
    const torch::Tensor pos = torch::arange(max_len, torch::kFloat).unsqueeze(1);
    const torch::Tensor div =
        torch::exp(torch::arange(0, d, 2, torch::kFloat) * (-std::log(10000.0) / static_cast<double>(d)));
    torch::Tensor pe = torch::zeros({max_len, d});
    pe.index_put_({torch::indexing::Slice(), torch::indexing::Slice(0, torch::indexing::None, 2)},
                  torch::sin(pos * div));
    pe.index_put_({torch::indexing::Slice(), torch::indexing::Slice(1, torch::indexing::None, 2)},
                  torch::cos(pos * div));
    return pe.unsqueeze(1);  // [max_len, 1, d]
}

// A named container so that parameter names read "input_process.poseEmbedding.weight" and so on.
struct Named : torch::nn::Module {};

}  // namespace

MdmConfig read_mdm_config(const std::string& path) {
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(read_file_text(path));
    } catch (const nlohmann::json::exception& e) {
        throw Error(path, "json", "a JSON object of MDM arguments", e.what());
    }
    MdmConfig c;
    auto get = [&](const char* key, int64_t& field) {
        if (j.contains(key)) {
            if (!j[key].is_number_integer()) throw Error(path, key, "an integer");
            field = j[key].get<int64_t>();
        }
    };
    get("njoints", c.njoints);
    get("latent_dim", c.latent_dim);
    get("ff_size", c.ff_size);
    get("num_layers", c.num_layers);
    get("num_heads", c.num_heads);
    get("pos_embed_max_len", c.max_len);
    if (j.contains("dropout")) c.dropout = j["dropout"].get<double>();
    if (j.contains("mask_frames")) c.mask_frames = j["mask_frames"].get<bool>();
    if (j.contains("arch") && j["arch"] != "trans_enc") throw Error(path, "arch", "trans_enc", j["arch"].dump());
    return c;
}

MdmImpl::MdmImpl(const MdmConfig& c) : config_(c) {
    namespace nn = torch::nn;
    auto input_process = register_module("input_process", std::make_shared<Named>());
    pose_embedding_ = input_process->register_module("poseEmbedding", nn::Linear(c.njoints, c.latent_dim));
    auto embed_timestep = register_module("embed_timestep", std::make_shared<Named>());
    time_embed_ = embed_timestep->register_module(
        "time_embed",
        nn::Sequential(nn::Linear(c.latent_dim, c.latent_dim), nn::SiLU(), nn::Linear(c.latent_dim, c.latent_dim)));
    embed_text_ = register_module("embed_text", nn::Linear(c.text_dim, c.latent_dim));
    EncoderOptions encoder;
    encoder.d_model = c.latent_dim;
    encoder.nhead = c.num_heads;
    encoder.dim_feedforward = c.ff_size;
    encoder.num_layers = c.num_layers;
    encoder.dropout = c.dropout;
    encoder.gelu = true;
    encoder_ = register_module("seqTransEncoder", TransformerEncoder(encoder));
    auto output_process = register_module("output_process", std::make_shared<Named>());
    pose_final_ = output_process->register_module("poseFinal", nn::Linear(c.latent_dim, c.njoints));
    pe_ = register_buffer("pe", sinusoidal_table(c.max_len, c.latent_dim));
}

torch::Tensor MdmImpl::forward(const torch::Tensor& x, const torch::Tensor& timesteps, const torch::Tensor& text,
                               bool uncond, const torch::Tensor& lengths) {
    const int64_t frames = x.size(3);
    // Condition token [1, B, d]: time embedding + text embedding.
    const torch::Tensor t_emb = time_embed_->forward(pe_.index_select(0, timesteps).squeeze(1)).unsqueeze(0);
    const torch::Tensor text_in = uncond ? torch::zeros_like(text) : text;
    const torch::Tensor emb = t_emb + embed_text_->forward(text_in).unsqueeze(0);
    // Frames [F, B, d]; then [F + 1, B, d] with positions added.
    const torch::Tensor h = pose_embedding_->forward(x.squeeze(2).permute({2, 0, 1}));
    torch::Tensor seq = torch::cat({emb, h}, 0);
    seq = hashed_dropout(seq + pe_.index({torch::indexing::Slice(0, frames + 1)}), config_.dropout, is_training());
    torch::Tensor padding;  // [B, F + 1], true where attention must not look; the condition token is always seen
    if (config_.mask_frames && lengths.defined()) {
        const torch::Tensor f = torch::arange(frames, torch::TensorOptions().dtype(torch::kLong).device(x.device()));
        const torch::Tensor pad = f.unsqueeze(0) >= lengths.to(torch::kLong).unsqueeze(1);
        padding = torch::cat({torch::zeros({x.size(0), 1}, pad.options()), pad}, 1);
    }
    const torch::Tensor out = encoder_->forward(seq, padding).index({torch::indexing::Slice(1, torch::indexing::None)});
    return pose_final_->forward(out).permute({1, 2, 0}).unsqueeze(2);  // [B, 263, 1, F]
}

torch::Tensor MdmImpl::forward_guided(const torch::Tensor& x, const torch::Tensor& timesteps, const torch::Tensor& text,
                                      double scale, const torch::Tensor& lengths) {
    const int64_t b = x.size(0);
    // Both passes in one forward: the second half of the batch carries a zeroed text.
    const torch::Tensor texts = torch::cat({text, torch::zeros_like(text)}, 0);
    const torch::Tensor both = forward(torch::cat({x, x}, 0), torch::cat({timesteps, timesteps}, 0), texts, false,
                                       lengths.defined() ? torch::cat({lengths, lengths}, 0) : lengths);
    const torch::Tensor cond = both.narrow(0, 0, b), uncond = both.narrow(0, b, b);
    return uncond + scale * (cond - uncond);
}

void load_mdm_weights(Mdm& model, const std::string& path, const std::string& other_prefix) {
    StateDictLayout layout;
    if (!other_prefix.empty())
        layout.foreign = [other_prefix](const std::string& key) { return key.rfind(other_prefix, 0) == 0; };
    layout.owner = "a key of the MDM state dict";
    load_state_dict(*model, path, layout);
}

}  // namespace t2imu
