// A BERT-family sentence encoder for users who hold all-MiniLM-L6-v2 (or any BERT) weights: the Hugging Face
// BertModel with its state-dict key names (embeddings.*, encoder.layer.N.*), post-norm layers with GELU, then
// sentence-transformers' mean pooling over the attention mask and L2 normalisation. Tokens come from
// text/wordpiece.hpp. The weights cannot be downloaded here; the encoder is tested on random weights for
// shapes, masking and key handling.
#pragma once
#include <torch/torch.h>

#include <memory>
#include <string>
#include <vector>

#include "text/wordpiece.hpp"

namespace t2imu {

struct BertConfig {
    int64_t vocab_size = 30522, hidden = 384, layers = 6, heads = 12, intermediate = 1536, max_positions = 512,
            type_vocab = 2;
    double layer_norm_eps = 1e-12;
};

class BertEncoderImpl : public torch::nn::Module {
public:
    explicit BertEncoderImpl(const BertConfig& config);
    // ids [B, L] int64 (0 = [PAD]) -> unit sentence vectors [B, hidden].
    torch::Tensor forward(const torch::Tensor& ids, const torch::Tensor& attention_mask);
    // Right-pads token-id rows with [PAD] = 0 and encodes them.
    torch::Tensor encode(const std::vector<std::vector<int64_t>>& ids);
    // Sentences through the WordPiece tokenizer ([CLS] ... [SEP], at most max_tokens ids) -> [B, hidden].
    void set_tokenizer(std::shared_ptr<const WordPieceTokenizer> tokenizer, size_t max_tokens = 256);
    torch::Tensor encode(const std::vector<std::string>& sentences);
    const BertConfig& config() const { return config_; }

private:
    struct Layer {
        torch::nn::Linear query{nullptr}, key{nullptr}, value{nullptr}, attention_out{nullptr}, intermediate{nullptr},
            output{nullptr};
        torch::nn::LayerNorm attention_norm{nullptr}, output_norm{nullptr};
    };
    BertConfig config_;
    std::shared_ptr<const WordPieceTokenizer> tokenizer_;
    size_t max_tokens_ = 256;
    torch::nn::Embedding words_{nullptr}, positions_{nullptr}, types_{nullptr};
    torch::nn::LayerNorm embedding_norm_{nullptr};
    std::vector<Layer> layers_;
};
TORCH_MODULE(BertEncoder);

// Loads Hugging Face BertModel weights by name (nn/state_dict.hpp), strictly: an optional "bert." prefix; the
// pooler, a "cls." head and the position_ids buffer are skipped; a missing, mis-shaped or other key is refused.
void load_bert_weights(BertEncoder& model, const std::string& safetensors_path);

// The sizes a BertModel file implies (vocabulary, width, layers, feed-forward width, positions); the head count
// is not in the weights (all-MiniLM-L6-v2: 12) and is given. Throws Error naming the key that is missing.
BertConfig read_bert_config(const std::string& safetensors_path, int64_t heads);

}  // namespace t2imu
