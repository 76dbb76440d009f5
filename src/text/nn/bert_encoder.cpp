#include "text/nn/bert_encoder.hpp"

#include <cmath>

#include "core/error.hpp"
#include "nn/state_dict.hpp"

namespace t2imu {

BertEncoderImpl::BertEncoderImpl(const BertConfig& c) : config_(c) {
    words_ = register_module_at(*this, "embeddings.word_embeddings", torch::nn::Embedding(c.vocab_size, c.hidden));
    positions_ =
        register_module_at(*this, "embeddings.position_embeddings", torch::nn::Embedding(c.max_positions, c.hidden));
    types_ =
        register_module_at(*this, "embeddings.token_type_embeddings", torch::nn::Embedding(c.type_vocab, c.hidden));
    embedding_norm_ =
        register_module_at(*this, "embeddings.LayerNorm",
                           torch::nn::LayerNorm(torch::nn::LayerNormOptions({c.hidden}).eps(c.layer_norm_eps)));
    for (int64_t i = 0; i < c.layers; ++i) {
        const std::string p = "encoder.layer." + std::to_string(i) + ".";
        Layer l;
        l.query = register_module_at(*this, p + "attention.self.query", torch::nn::Linear(c.hidden, c.hidden));
        l.key = register_module_at(*this, p + "attention.self.key", torch::nn::Linear(c.hidden, c.hidden));
        l.value = register_module_at(*this, p + "attention.self.value", torch::nn::Linear(c.hidden, c.hidden));
        l.attention_out =
            register_module_at(*this, p + "attention.output.dense", torch::nn::Linear(c.hidden, c.hidden));
        l.attention_norm =
            register_module_at(*this, p + "attention.output.LayerNorm",
                               torch::nn::LayerNorm(torch::nn::LayerNormOptions({c.hidden}).eps(c.layer_norm_eps)));
        l.intermediate =
            register_module_at(*this, p + "intermediate.dense", torch::nn::Linear(c.hidden, c.intermediate));
        l.output = register_module_at(*this, p + "output.dense", torch::nn::Linear(c.intermediate, c.hidden));
        l.output_norm =
            register_module_at(*this, p + "output.LayerNorm",
                               torch::nn::LayerNorm(torch::nn::LayerNormOptions({c.hidden}).eps(c.layer_norm_eps)));
        layers_.push_back(l);
    }
}

torch::Tensor BertEncoderImpl::forward(const torch::Tensor& ids, const torch::Tensor& mask) {
    const int64_t B = ids.size(0), L = ids.size(1), H = config_.hidden, heads = config_.heads, d = H / heads;
    if (L > config_.max_positions)
        throw Error("bert", "tokens", "at most " + std::to_string(config_.max_positions), std::to_string(L));
    const torch::Tensor positions =
        torch::arange(L, torch::TensorOptions().dtype(torch::kInt64).device(ids.device())).unsqueeze(0).expand({B, L});
    torch::Tensor h = words_->forward(ids) + positions_->forward(positions) + types_->forward(torch::zeros_like(ids));
    h = embedding_norm_->forward(h);
    // Additive attention mask: padded keys get a large negative score.
    const torch::Tensor bias = (1 - mask.to(torch::kFloat32)).view({B, 1, 1, L}) * -1e9;
    for (Layer& l : layers_) {
        const auto split = [&](const torch::Tensor& x) {
            return x.view({B, L, heads, d}).transpose(1, 2);
        };  // [B, heads, L, d]
        const torch::Tensor q = split(l.query->forward(h)), k = split(l.key->forward(h)),
                            v = split(l.value->forward(h));
        const torch::Tensor scores = torch::matmul(q, k.transpose(-1, -2)) / std::sqrt(static_cast<double>(d)) + bias;
        const torch::Tensor context = torch::matmul(torch::softmax(scores, -1), v).transpose(1, 2).reshape({B, L, H});
        h = l.attention_norm->forward(h + l.attention_out->forward(context));
        h = l.output_norm->forward(h + l.output->forward(torch::gelu(l.intermediate->forward(h))));
    }
    const torch::Tensor m = mask.to(torch::kFloat32).unsqueeze(2);
    const torch::Tensor pooled = (h * m).sum(1) / m.sum(1).clamp_min(1e-9);
    return torch::nn::functional::normalize(pooled, torch::nn::functional::NormalizeFuncOptions().dim(1));
}

torch::Tensor BertEncoderImpl::encode(const std::vector<std::vector<int64_t>>& ids) {
    size_t longest = 1;
    for (const auto& row : ids) longest = std::max(longest, row.size());
    torch::Tensor t = torch::zeros({static_cast<int64_t>(ids.size()), static_cast<int64_t>(longest)}, torch::kInt64),
                  m = torch::zeros_like(t);
    for (size_t b = 0; b < ids.size(); ++b)
        for (size_t k = 0; k < ids[b].size(); ++k) {
            t[static_cast<int64_t>(b)][static_cast<int64_t>(k)] = ids[b][k];
            m[static_cast<int64_t>(b)][static_cast<int64_t>(k)] = 1;
        }
    const torch::Device device = words_->weight.device();
    return forward(t.to(device), m.to(device));
}

void BertEncoderImpl::set_tokenizer(std::shared_ptr<const WordPieceTokenizer> tokenizer, size_t max_tokens) {
    tokenizer_ = std::move(tokenizer);
    max_tokens_ = std::min<size_t>(max_tokens, static_cast<size_t>(config_.max_positions));
}

torch::Tensor BertEncoderImpl::encode(const std::vector<std::string>& sentences) {
    if (!tokenizer_)
        throw Error("bert", "tokenizer", "a WordPiece tokenizer (set_tokenizer) before encoding sentences");
    std::vector<std::vector<int64_t>> ids;
    for (const std::string& s : sentences) ids.push_back(tokenizer_->encode(s, max_tokens_));
    return encode(ids);
}

namespace {

// BertForMaskedLM and friends keep the encoder under "bert."; a bare BertModel (sentence-transformers) does not.
std::string bert_prefix(const SafeTensors& st) {
    return st.tensors.count("bert.embeddings.word_embeddings.weight") ? "bert." : "";
}

}  // namespace

BertConfig read_bert_config(const std::string& path, int64_t heads) {
    const SafeTensors st = read_safetensors(path);
    const std::string prefix = bert_prefix(st);
    const auto shape = [&](const std::string& name) {
        const auto it = st.tensors.find(prefix + name);
        if (it == st.tensors.end() || it->second.shape.size() != 2)
            throw Error(path, prefix + name, "a matrix", it == st.tensors.end() ? "missing" : it->second.shape_str());
        return it->second.shape;
    };
    BertConfig c;
    c.vocab_size = shape("embeddings.word_embeddings.weight")[0];
    c.hidden = shape("embeddings.word_embeddings.weight")[1];
    c.max_positions = shape("embeddings.position_embeddings.weight")[0];
    c.type_vocab = shape("embeddings.token_type_embeddings.weight")[0];
    c.intermediate = shape("encoder.layer.0.intermediate.dense.weight")[0];
    c.layers = 0;
    while (st.tensors.count(prefix + "encoder.layer." + std::to_string(c.layers) + ".attention.self.query.weight"))
        ++c.layers;
    if (heads < 1 || c.hidden % heads != 0)
        throw Error(path, "heads", "a divisor of the width " + std::to_string(c.hidden), std::to_string(heads));
    c.heads = heads;
    return c;
}

void load_bert_weights(BertEncoder& model, const std::string& path) {
    const SafeTensors st = read_safetensors(path);
    const std::string prefix = bert_prefix(st);
    StateDictLayout layout = prefixed_layout(prefix);
    layout.foreign = [prefix](const std::string& key) {
        // The pooler (unused by mean pooling), a task head, and the position-id buffer older files carry.
        return key.rfind(prefix + "pooler.", 0) == 0 || key.rfind("cls.", 0) == 0 ||
               key == prefix + "embeddings.position_ids";
    };
    layout.owner = "a key of BertModel";
    load_state_dict(*model, st, path, layout);
}

}  // namespace t2imu
