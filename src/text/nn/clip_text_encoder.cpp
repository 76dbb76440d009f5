#include "text/nn/clip_text_encoder.hpp"

#include <cmath>
#include <limits>
#include <set>

#include "core/error.hpp"
#include "core/parse.hpp"
#include "nn/state_dict.hpp"

namespace t2imu {

namespace {

std::string leaf(const std::string& path) { return path.substr(path.rfind('.') + 1); }

bool starts_with(const std::string& s, const std::string& p) { return s.compare(0, p.size(), p) == 0; }

// Where a file keeps the text tower: OpenAI's names under `prefix`, or Hugging Face's names.
struct Layout {
    bool hugging_face = false;
    std::string prefix;
};

const char* const kHfTokens = "text_model.embeddings.token_embedding.weight";

Layout detect_layout(const SafeTensors& st, const std::string& path) {
    if (st.tensors.count(kHfTokens)) return {true, ""};
    if (st.tensors.count("token_embedding.weight")) return {false, ""};
    for (const auto& [key, a] : st.tensors)
        if (ends_with(key, ".token_embedding.weight") && key.find("text_model.") == std::string::npos)
            return {false, key.substr(0, key.size() - std::string("token_embedding.weight").size())};
    throw Error(
        path, "token_embedding.weight",
        "CLIP text-tower weights under OpenAI names (optionally prefixed, e.g. clip_model.) or Hugging Face names (" +
            std::string(kHfTokens) + ")",
        "neither");
}

// Hugging Face's key(s) for one of OpenAI's parameter names; in_proj_* maps to the three of q, k, v.
std::vector<std::string> hugging_face_keys(const std::string& name) {
    if (name == "token_embedding.weight") return {kHfTokens};
    if (name == "positional_embedding") return {"text_model.embeddings.position_embedding.weight"};
    if (name == "text_projection") return {"text_projection.weight"};
    if (starts_with(name, "ln_final.")) return {"text_model.final_layer_norm." + leaf(name)};
    const std::string blocks = "transformer.resblocks.";
    const size_t dot = name.find('.', blocks.size());
    const std::string layer = "text_model.encoder.layers." + name.substr(blocks.size(), dot - blocks.size()) + ".";
    const std::string rest = name.substr(dot + 1);
    if (rest == "attn.in_proj_weight" || rest == "attn.in_proj_bias") {
        const std::string kind = rest == "attn.in_proj_weight" ? "weight" : "bias";
        return {layer + "self_attn.q_proj." + kind, layer + "self_attn.k_proj." + kind,
                layer + "self_attn.v_proj." + kind};
    }
    const std::pair<const char*, const char*> renames[] = {{"ln_1.", "layer_norm1."},
                                                           {"ln_2.", "layer_norm2."},
                                                           {"attn.out_proj.", "self_attn.out_proj."},
                                                           {"mlp.c_fc.", "mlp.fc1."},
                                                           {"mlp.c_proj.", "mlp.fc2."}};
    for (const auto& [from, to] : renames)
        if (starts_with(rest, from)) return {layer + to + rest.substr(std::string(from).size())};
    return {layer + rest};
}

// Entries a full CLIP checkpoint holds besides the text tower.
bool ignored(const Layout& layout, const std::string& key) {
    if (layout.hugging_face)
        return starts_with(key, "vision_model.") || starts_with(key, "visual_projection.") || key == "logit_scale" ||
               ends_with(key, "position_ids");
    if (!starts_with(key, layout.prefix)) return true;  // the rest of a prefixed state dict, e.g. MDM's own weights
    const std::string name = key.substr(layout.prefix.size());
    return starts_with(name, "visual.") || name == "logit_scale" || name == "context_length" || name == "vocab_size" ||
           name == "input_resolution";
}

}  // namespace

ClipTextEncoderImpl::ClipTextEncoderImpl(const ClipTextConfig& c) : config_(c) {
    if (c.width % c.heads != 0)
        throw Error("clip", "heads", "a divisor of the width " + std::to_string(c.width), std::to_string(c.heads));
    const int64_t W = c.width;
    token_embedding_ = register_module_at(*this, "token_embedding", torch::nn::Embedding(c.vocab_size, W));
    positional_embedding_ =
        register_parameter_at(*this, "positional_embedding", torch::randn({c.context_length, W}) * 0.01);
    for (int64_t i = 0; i < c.layers; ++i) {
        const std::string p = "transformer.resblocks." + std::to_string(i) + ".";
        Block b;
        b.ln_1 = register_module_at(*this, p + "ln_1", torch::nn::LayerNorm(torch::nn::LayerNormOptions({W})));
        b.in_proj_weight = register_parameter_at(*this, p + "attn.in_proj_weight",
                                                 torch::randn({3 * W, W}) / std::sqrt(static_cast<double>(W)));
        b.in_proj_bias = register_parameter_at(*this, p + "attn.in_proj_bias", torch::zeros({3 * W}));
        b.out_proj = register_module_at(*this, p + "attn.out_proj", torch::nn::Linear(W, W));
        b.ln_2 = register_module_at(*this, p + "ln_2", torch::nn::LayerNorm(torch::nn::LayerNormOptions({W})));
        b.c_fc = register_module_at(*this, p + "mlp.c_fc", torch::nn::Linear(W, 4 * W));
        b.c_proj = register_module_at(*this, p + "mlp.c_proj", torch::nn::Linear(4 * W, W));
        blocks_.push_back(b);
    }
    ln_final_ = register_module_at(*this, "ln_final", torch::nn::LayerNorm(torch::nn::LayerNormOptions({W})));
    text_projection_ = register_parameter_at(*this, "text_projection",
                                             torch::randn({W, c.embed_dim}) / std::sqrt(static_cast<double>(W)));
    // Frozen in MDM: never trained here either.
    for (auto& p : parameters()) p.set_requires_grad(false);
}

torch::Tensor ClipTextEncoderImpl::hidden_states(const torch::Tensor& ids) {
    if (ids.dim() != 2 || ids.size(1) < 1 || ids.size(1) > config_.context_length)
        throw Error("clip", "token ids", "[batch, 1 to " + std::to_string(config_.context_length) + "]",
                    c10::str(ids.sizes()));
    const int64_t B = ids.size(0), L = ids.size(1), W = config_.width, H = config_.heads, d = W / H;
    torch::Tensor x = token_embedding_->forward(ids) + positional_embedding_.narrow(0, 0, L);
    // Causal: position i attends to positions <= i only.
    const torch::Tensor causal = torch::full({L, L}, -std::numeric_limits<float>::infinity(), x.options()).triu(1);
    for (Block& b : blocks_) {
        const std::vector<torch::Tensor> qkv =
            torch::nn::functional::linear(b.ln_1->forward(x), b.in_proj_weight, b.in_proj_bias).chunk(3, -1);
        const auto heads = [&](const torch::Tensor& t) {
            return t.reshape({B, L, H, d}).transpose(1, 2);
        };  // [B, H, L, d]
        const torch::Tensor scores =
            torch::matmul(heads(qkv[0]), heads(qkv[1]).transpose(-1, -2)) / std::sqrt(static_cast<double>(d)) + causal;
        const torch::Tensor context =
            torch::matmul(torch::softmax(scores, -1), heads(qkv[2])).transpose(1, 2).reshape({B, L, W});
        x = x + b.out_proj->forward(context);
        const torch::Tensor h = b.c_fc->forward(b.ln_2->forward(x));
        x = x + b.c_proj->forward(h * torch::sigmoid(1.702 * h));
    }
    return ln_final_->forward(x);
}

torch::Tensor ClipTextEncoderImpl::forward(const torch::Tensor& ids) {
    const torch::Tensor h = hidden_states(ids);
    const torch::Tensor eot = ids.argmax(-1);
    const torch::Tensor pooled = h.index({torch::arange(ids.size(0), eot.options()), eot});  // [B, W]
    return pooled.matmul(text_projection_);
}

void ClipTextEncoderImpl::set_tokenizer(std::shared_ptr<const ClipBpeTokenizer> tokenizer) {
    if (tokenizer && static_cast<int64_t>(tokenizer->vocab_size()) != config_.vocab_size)
        throw Error("clip", "vocabulary",
                    std::to_string(config_.vocab_size) + " entries, as many as the token embedding has",
                    std::to_string(tokenizer->vocab_size()) + " from the merges file");
    tokenizer_ = std::move(tokenizer);
}

torch::Tensor ClipTextEncoderImpl::encode(const std::vector<std::string>& captions) {
    if (!tokenizer_) throw Error("clip", "tokenizer", "a BPE tokenizer set before encoding captions");
    const int64_t C = config_.context_length;
    const int64_t context = config_.mdm_text_tokens > 1 && config_.mdm_text_tokens < C ? config_.mdm_text_tokens : C;
    torch::Tensor ids = torch::zeros({static_cast<int64_t>(captions.size()), C}, torch::kInt64);
    for (size_t b = 0; b < captions.size(); ++b) {
        const std::vector<int64_t> row = tokenizer_->tokenize(captions[b], context, true);
        std::copy(row.begin(), row.end(), ids[static_cast<int64_t>(b)].data_ptr<int64_t>());
    }
    return forward(ids.to(token_embedding_->weight.device()));
}

void load_clip_text_weights(ClipTextEncoder& model, const std::string& path) {
    const SafeTensors st = read_safetensors(path);
    const Layout layout = detect_layout(st, path);
    StateDictLayout keys;
    keys.source = [layout](const std::string& name) {
        if (!layout.hugging_face) return TensorSource{{layout.prefix + name}, false};
        // Hugging Face stores q, k, v apart (each a third of in_proj) and the projection as a Linear weight (P^T).
        return TensorSource{hugging_face_keys(name), name == "text_projection"};
    };
    keys.foreign = [layout](const std::string& key) { return ignored(layout, key); };
    keys.owner = "a key of CLIP's text tower";
    load_state_dict(*model, st, path, keys);
}

ClipTextConfig read_clip_text_config(const std::string& path) {
    const SafeTensors st = read_safetensors(path);
    const Layout layout = detect_layout(st, path);
    const auto shape = [&](const std::string& openai_name) {
        const std::string key = layout.hugging_face ? hugging_face_keys(openai_name)[0] : layout.prefix + openai_name;
        const auto it = st.tensors.find(key);
        if (it == st.tensors.end() || it->second.shape.size() != 2)
            throw Error(path, key, "a matrix", it == st.tensors.end() ? "missing" : it->second.shape_str());
        return it->second.shape;
    };
    ClipTextConfig c;
    c.vocab_size = shape("token_embedding.weight")[0];
    c.width = shape("token_embedding.weight")[1];
    c.context_length = shape("positional_embedding")[0];
    c.embed_dim = shape("text_projection")[layout.hugging_face ? 0 : 1];
    c.heads = std::max<int64_t>(1, c.width / 64);  // CLIP's rule: 64-wide heads
    const std::string blocks =
        layout.hugging_face ? "text_model.encoder.layers." : layout.prefix + "transformer.resblocks.";
    std::set<std::string> layers;
    for (const auto& [key, a] : st.tensors)
        if (starts_with(key, blocks))
            layers.insert(key.substr(blocks.size(), key.find('.', blocks.size()) - blocks.size()));
    c.layers = static_cast<int64_t>(layers.size());
    return c;
}

}  // namespace t2imu
