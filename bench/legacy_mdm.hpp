// MDM as this project built it up to 70e56c2, from libtorch's modules (TransformerEncoder, Dropout), restated for
// the benchmarks that measure today's code against it (bench_train_step.cpp, bench_mdm.cpp). Same computation
// as src/diffusion/mdm.hpp then; parameter names are not MDM's official ones (nothing loads into it).
#pragma once
#include <cmath>

#include "diffusion/mdm.hpp"

namespace t2imu {

struct LegacyMdmImpl : torch::nn::Module {
    explicit LegacyMdmImpl(const MdmConfig& c) : c_(c) {
        namespace nn = torch::nn;
        pose_embedding = register_module("pose", nn::Linear(c.njoints, c.latent_dim));
        time_embed = register_module("time", nn::Sequential(nn::Linear(c.latent_dim, c.latent_dim), nn::SiLU(),
                                                            nn::Linear(c.latent_dim, c.latent_dim)));
        embed_text = register_module("text", nn::Linear(c.text_dim, c.latent_dim));
        auto layer = nn::TransformerEncoderLayer(nn::TransformerEncoderLayerOptions(c.latent_dim, c.num_heads)
                                                     .dim_feedforward(c.ff_size)
                                                     .dropout(c.dropout)
                                                     .activation(torch::kGELU));
        encoder =
            register_module("encoder", nn::TransformerEncoder(nn::TransformerEncoderOptions(layer, c.num_layers)));
        pose_final = register_module("final", nn::Linear(c.latent_dim, c.njoints));
        pos_dropout = register_module("pos_dropout", nn::Dropout(c.dropout));
        const torch::Tensor pos = torch::arange(c.max_len, torch::kFloat).unsqueeze(1);
        const torch::Tensor div = torch::exp(torch::arange(0, c.latent_dim, 2, torch::kFloat) *
                                             (-std::log(10000.0) / static_cast<double>(c.latent_dim)));
        pe = torch::stack({torch::sin(pos * div), torch::cos(pos * div)}, 2).flatten(1).unsqueeze(1);
    }
    torch::Tensor forward(const torch::Tensor& x, const torch::Tensor& t, const torch::Tensor& text,
                          const torch::Tensor& lengths = {}) {
        const int64_t frames = x.size(3);
        const torch::Tensor emb =
            time_embed->forward(pe.index_select(0, t).squeeze(1)).unsqueeze(0) + embed_text->forward(text).unsqueeze(0);
        torch::Tensor seq = torch::cat({emb, pose_embedding->forward(x.squeeze(2).permute({2, 0, 1}))}, 0);
        seq = pos_dropout->forward(seq + pe.index({torch::indexing::Slice(0, frames + 1)}));
        torch::Tensor padding;  // none without lengths (sampling a batch of equal lengths)
        if (lengths.defined()) {
            const torch::Tensor pad = torch::arange(frames).unsqueeze(0) >= lengths.unsqueeze(1);
            padding = torch::cat({torch::zeros({x.size(0), 1}, pad.options()), pad}, 1);
        }
        const torch::Tensor out =
            encoder->forward(seq, {}, padding).index({torch::indexing::Slice(1, torch::indexing::None)});
        return pose_final->forward(out).permute({1, 2, 0}).unsqueeze(2);
    }
    MdmConfig c_;
    torch::nn::Linear pose_embedding{nullptr}, embed_text{nullptr}, pose_final{nullptr};
    torch::nn::Sequential time_embed{nullptr};
    torch::nn::TransformerEncoder encoder{nullptr};
    torch::nn::Dropout pos_dropout{nullptr};
    torch::Tensor pe;
};
TORCH_MODULE(LegacyMdm);

}  // namespace t2imu
