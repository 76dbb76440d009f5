#include "diffusion/bert_encoder.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/safetensors.hpp"

namespace t2imu {

namespace {

// libtorch names submodules without dots; nested holder modules give the Hugging Face paths.
torch::nn::Module& holder(torch::nn::Module& parent, const std::string& name) {
    for (const auto& child : parent.named_children())
        if (child.key() == name) return *child.value();
    return *parent.register_module(name, std::make_shared<torch::nn::Module>());
}

// Registers `module` at the dotted `path` below `root`, creating the holders on the way.
template <class M> M at_path(torch::nn::Module& root, const std::string& path, M module) {
    torch::nn::Module* parent = &root;
    size_t start = 0;
    for (size_t dot = path.find('.'); dot != std::string::npos; start = dot + 1, dot = path.find('.', start))
        parent = &holder(*parent, path.substr(start, dot - start));
    return parent->register_module(path.substr(start), module);
}

}  // namespace

BertEncoderImpl::BertEncoderImpl(const BertConfig& c) : config_(c) {
    words_ = at_path(*this, "embeddings.word_embeddings", torch::nn::Embedding(c.vocab_size, c.hidden));
    positions_ = at_path(*this, "embeddings.position_embeddings", torch::nn::Embedding(c.max_positions, c.hidden));
    types_ = at_path(*this, "embeddings.token_type_embeddings", torch::nn::Embedding(c.type_vocab, c.hidden));
    embedding_norm_ = at_path(*this, "embeddings.LayerNorm", torch::nn::LayerNorm(torch::nn::LayerNormOptions({c.hidden}).eps(c.layer_norm_eps)));
    for (int64_t i = 0; i < c.layers; ++i) {
        const std::string p = "encoder.layer." + std::to_string(i) + ".";
        Layer l;
        l.query = at_path(*this, p + "attention.self.query", torch::nn::Linear(c.hidden, c.hidden));
        l.key = at_path(*this, p + "attention.self.key", torch::nn::Linear(c.hidden, c.hidden));
        l.value = at_path(*this, p + "attention.self.value", torch::nn::Linear(c.hidden, c.hidden));
        l.attention_out = at_path(*this, p + "attention.output.dense", torch::nn::Linear(c.hidden, c.hidden));
        l.attention_norm = at_path(*this, p + "attention.output.LayerNorm", torch::nn::LayerNorm(torch::nn::LayerNormOptions({c.hidden}).eps(c.layer_norm_eps)));
        l.intermediate = at_path(*this, p + "intermediate.dense", torch::nn::Linear(c.hidden, c.intermediate));
        l.output = at_path(*this, p + "output.dense", torch::nn::Linear(c.intermediate, c.hidden));
        l.output_norm = at_path(*this, p + "output.LayerNorm", torch::nn::LayerNorm(torch::nn::LayerNormOptions({c.hidden}).eps(c.layer_norm_eps)));
        layers_.push_back(l);
    }
}

torch::Tensor BertEncoderImpl::forward(const torch::Tensor& ids, const torch::Tensor& mask) {
    const int64_t B = ids.size(0), L = ids.size(1), H = config_.hidden, heads = config_.heads, d = H / heads;
    if (L > config_.max_positions) throw Error("bert", "tokens", "at most " + std::to_string(config_.max_positions), std::to_string(L));
    const torch::Tensor positions = torch::arange(L, torch::kInt64).unsqueeze(0).expand({B, L});
    torch::Tensor h = words_->forward(ids) + positions_->forward(positions) + types_->forward(torch::zeros_like(ids));
    h = embedding_norm_->forward(h);
    // Additive attention mask: padded keys get a large negative score.
    const torch::Tensor bias = (1 - mask.to(torch::kFloat32)).view({B, 1, 1, L}) * -1e9;
    for (Layer& l : layers_) {
        const auto split = [&](const torch::Tensor& x) { return x.view({B, L, heads, d}).transpose(1, 2); };  // [B, heads, L, d]
        const torch::Tensor q = split(l.query->forward(h)), k = split(l.key->forward(h)), v = split(l.value->forward(h));
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
    torch::Tensor t = torch::zeros({static_cast<int64_t>(ids.size()), static_cast<int64_t>(longest)}, torch::kInt64), m = torch::zeros_like(t);
    for (size_t b = 0; b < ids.size(); ++b)
        for (size_t k = 0; k < ids[b].size(); ++k) {
            t[static_cast<int64_t>(b)][static_cast<int64_t>(k)] = ids[b][k];
            m[static_cast<int64_t>(b)][static_cast<int64_t>(k)] = 1;
        }
    return forward(t, m);
}

void load_bert_weights(BertEncoder& model, const std::string& path) {
    const SafeTensors st = read_safetensors(path);
    torch::NoGradGuard no_grad;
    for (auto& p : model->named_parameters()) {
        auto it = st.tensors.find(p.key());
        if (it == st.tensors.end()) it = st.tensors.find("bert." + p.key());
        if (it == st.tensors.end()) throw Error(path, p.key(), "a tensor of shape " + c10::str(p.value().sizes()), "missing");
        if (it->second.shape != std::vector<int64_t>(p.value().sizes().begin(), p.value().sizes().end()))
            throw Error(path, p.key(), "shape " + c10::str(p.value().sizes()), it->second.shape_str());
        std::vector<float> v = it->second.to<float>();
        p.value().copy_(torch::from_blob(v.data(), it->second.shape, torch::kFloat));
    }
}

}  // namespace t2imu
