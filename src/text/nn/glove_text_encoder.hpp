// The default text encoder, trained jointly with the motion model: frozen GloVe word vectors (public domain;
// text/word_vectors.hpp) under a small trainable transformer, pooled to one sentence vector.
//
// Why this design: pretrained sentence encoders (CLIP, MiniLM) cannot be downloaded here, and a few thousand
// captions are far too few to learn word meanings from scratch. GloVe supplies word meaning (walk ~ stroll,
// jog ~ run) for 100k words; the transformer learns what the motion model needs from word order and
// combination ("walks backwards" vs "walks forwards", "slowly", "left hand"), which a bag of words cannot.
//   tokens  caption -> word indices (word_tokenizer.hpp), at most kMaxWords; unknown words -> a learned <unk>
//   embed   GloVe 100-d (a fixed buffer) or <unk> -> Linear 100 -> d, plus sinusoidal positions
//   encode  TransformerEncoder, `layers` post-norm layers, `heads` heads, GELU; padding masked out
//   pool    mean over the caption's words -> Linear d -> out_dim (MDM's text_dim, 512 by default), so the
//           encoder replaces CLIP in MDM without changing the denoiser.
// An empty caption encodes to the zero vector, the same as MDM's unconditional (zeroed) text feature.
#pragma once
#include <torch/torch.h>

#include <string>
#include <vector>

#include "text/word_vectors.hpp"

namespace t2imu {

struct GloveEncoderConfig {
    int64_t model_dim = 256, layers = 2, heads = 4, ff_size = 512, out_dim = 512;
    double dropout = 0.1;
    static constexpr int64_t kMaxWords = 40;
};

class GloveTextEncoderImpl : public torch::nn::Module {
public:
    GloveTextEncoderImpl(const WordVectors& vectors, const GloveEncoderConfig& config);

    // Word indices per caption (-1 = unknown) -> [B, out_dim].
    torch::Tensor forward(const std::vector<std::vector<int>>& captions);
    torch::Tensor encode(const std::vector<std::string>& captions);  // tokenises with the vocabulary first

private:
    const WordVectors& vectors_;
    GloveEncoderConfig config_;
    torch::Tensor glove_;    // [V, 100] buffer, not trained
    torch::Tensor unknown_;  // [100] parameter
    torch::Tensor pe_;       // [kMaxWords, model_dim]
    torch::nn::Linear project_in_{nullptr}, project_out_{nullptr};
    torch::nn::TransformerEncoder encoder_{nullptr};
};
TORCH_MODULE(GloveTextEncoder);

}  // namespace t2imu
