// The BERT sentence encoder on random weights: key names, loading, masking, pooling and normalisation.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/safetensors.hpp"
#include "diffusion/bert_encoder.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

BertConfig small() {
    BertConfig c;
    c.vocab_size = 200;
    c.hidden = 32;
    c.layers = 2;
    c.heads = 4;
    c.intermediate = 64;
    c.max_positions = 64;
    return c;
}

// The model's weights under Hugging Face names with the "bert." prefix, plus a pooler the encoder ignores.
void save_hf(BertEncoder& m, const std::string& path, const std::string& drop = "", bool wrong_shape = false) {
    SafeTensors st;
    for (const auto& p : m->named_parameters()) {
        if (p.key() == drop) continue;
        torch::Tensor v = p.value().detach().contiguous();
        if (wrong_shape && p.key() == "embeddings.word_embeddings.weight") v = v.narrow(0, 0, 10).contiguous();
        st.tensors["bert." + p.key()] = NdArray::from(std::vector<float>(v.data_ptr<float>(), v.data_ptr<float>() + v.numel()),
                                                      std::vector<int64_t>(v.sizes().begin(), v.sizes().end()));
    }
    st.tensors["bert.pooler.dense.weight"] = NdArray::from(std::vector<float>(32 * 32, 0.1f), {32, 32});
    write_safetensors(path, st);
}

}  // namespace

TEST(BertEncoder, HuggingFaceKeyNames) {
    BertEncoder m(small());
    std::vector<std::string> names;
    for (const auto& p : m->named_parameters()) names.push_back(p.key());
    for (const char* key : {"embeddings.word_embeddings.weight", "embeddings.LayerNorm.weight", "encoder.layer.0.attention.self.query.weight",
                            "encoder.layer.1.attention.output.LayerNorm.bias", "encoder.layer.1.intermediate.dense.weight",
                            "encoder.layer.0.output.dense.bias"})
        EXPECT_NE(std::find(names.begin(), names.end(), key), names.end()) << key;
    EXPECT_EQ(names.size(), 5u + 2 * 16u);  // 3 embeddings + LayerNorm (2) + 16 tensors per layer
}

TEST(BertEncoder, LoadsByNameMasksPaddingAndNormalises) {
    torch::manual_seed(3);
    BertEncoder source(small()), target(small());
    source->eval();
    target->eval();
    const std::string dir = test::scratch_dir("bert");
    save_hf(source, dir + "/w.safetensors");
    load_bert_weights(target, dir + "/w.safetensors");
    torch::NoGradGuard no_grad;
    const std::vector<std::vector<int64_t>> ids = {{101 % 200, 7, 19, 102 % 200}, {101 % 200, 7, 19, 44, 55, 66, 102 % 200}};
    const torch::Tensor a = source->encode(ids), b = target->encode(ids);
    EXPECT_EQ(a.sizes(), (std::vector<int64_t>{2, 32}));
    EXPECT_LT((a - b).abs().max().item<double>(), 1e-6);                                    // loaded exactly
    EXPECT_NEAR(a.norm(2, 1).min().item<double>(), 1.0, 1e-5);                              // unit vectors
    EXPECT_LT((source->encode({ids[0]})[0] - a[0]).abs().max().item<double>(), 1e-5);        // padding is invisible
    save_hf(source, dir + "/missing.safetensors", "encoder.layer.1.output.dense.weight");
    EXPECT_THROW(load_bert_weights(target, dir + "/missing.safetensors"), Error);
    save_hf(source, dir + "/shape.safetensors", "", true);
    EXPECT_THROW(load_bert_weights(target, dir + "/shape.safetensors"), Error);
}
