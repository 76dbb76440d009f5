// The BERT sentence encoder on random weights: key names, loading, masking, pooling and normalisation.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.hpp"
#include "core/npy.hpp"
#include "core/safetensors.hpp"
#include "diffusion/text_to_motion.hpp"
#include "nn/state_dict.hpp"
#include "test_util.hpp"
#include "text/nn/bert_encoder.hpp"

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
        st.tensors["bert." + p.key()] =
            NdArray::from(std::vector<float>(v.data_ptr<float>(), v.data_ptr<float>() + v.numel()),
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
    for (const char* key :
         {"embeddings.word_embeddings.weight", "embeddings.LayerNorm.weight",
          "encoder.layer.0.attention.self.query.weight", "encoder.layer.1.attention.output.LayerNorm.bias",
          "encoder.layer.1.intermediate.dense.weight", "encoder.layer.0.output.dense.bias"})
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
    const std::vector<std::vector<int64_t>> ids = {{101 % 200, 7, 19, 102 % 200},
                                                   {101 % 200, 7, 19, 44, 55, 66, 102 % 200}};
    const torch::Tensor a = source->encode(ids), b = target->encode(ids);
    EXPECT_EQ(a.sizes(), (std::vector<int64_t>{2, 32}));
    EXPECT_LT((a - b).abs().max().item<double>(), 1e-6);                               // loaded exactly
    EXPECT_NEAR(a.norm(2, 1).min().item<double>(), 1.0, 1e-5);                         // unit vectors
    EXPECT_LT((source->encode({ids[0]})[0] - a[0]).abs().max().item<double>(), 1e-5);  // padding is invisible
    save_hf(source, dir + "/missing.safetensors", "encoder.layer.1.output.dense.weight");
    EXPECT_THROW(load_bert_weights(target, dir + "/missing.safetensors"), Error);
    save_hf(source, dir + "/shape.safetensors", "", true);
    EXPECT_THROW(load_bert_weights(target, dir + "/shape.safetensors"), Error);
}

TEST(BertEncoder, RefusesAnUnexpectedKeyByName) {
    BertEncoder m(small());
    const std::string dir = test::scratch_dir("bert");
    save_hf(m, dir + "/w.safetensors");
    SafeTensors st = read_safetensors(dir + "/w.safetensors");
    st.tensors["bert.encoder.layer.9.output.dense.weight"] = NdArray::from(std::vector<float>(4, 0.f), {2, 2});
    write_safetensors(dir + "/extra.safetensors", st);
    try {
        load_bert_weights(m, dir + "/extra.safetensors");
        FAIL() << "an unexpected key was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bert.encoder.layer.9.output.dense.weight"), std::string::npos)
            << e.what();
    }
}

// model.json's "minilm" text encoder: sizes read from the weights, WordPiece tokens, frozen sentence vectors
// that reach MDM as its text feature; a width other than mdm.text_dim is refused naming the key.
TEST(BertEncoder, ModelFolderWithAMiniLMTextEncoder) {
    const std::string dir = test::scratch_dir("bert-model");
    torch::manual_seed(5);
    BertEncoder bert(small());
    bert->eval();
    save_hf(bert, dir + "/minilm.safetensors");
    {
        std::ofstream vocab(dir + "/vocab.txt");
        for (int i = 0; i < 200; ++i)
            vocab << (i == 0     ? "[PAD]"
                      : i == 100 ? "[UNK]"
                      : i == 101 ? "[CLS]"
                      : i == 102 ? "[SEP]"
                      : i == 7   ? "person"
                      : i == 19  ? "walks"
                                 : "tok" + std::to_string(i))
                  << "\n";
    }
    MdmConfig mc;
    mc.latent_dim = 32;
    mc.ff_size = 64;
    mc.num_layers = 1;
    mc.num_heads = 2;
    mc.text_dim = 32;
    Mdm mdm(mc);
    save_state_dict(*mdm, dir + "/weights.safetensors");
    write_npy(dir + "/Mean.npy", NdArray::from(std::vector<double>(263, 0.0), {263}));
    write_npy(dir + "/Std.npy", NdArray::from(std::vector<double>(263, 1.0), {263}));
    nlohmann::json meta = {
        {"mdm",
         {{"latent_dim", 32},
          {"ff_size", 64},
          {"num_layers", 1},
          {"num_heads", 2},
          {"dropout", 0.1},
          {"text_dim", 32},
          {"mask_frames", false}}},
        {"text_encoder", {{"kind", "minilm"}, {"weights", "minilm.safetensors"}, {"vocab", "vocab.txt"}, {"heads", 4}}},
        {"diffusion", {{"steps", 10}}}};
    std::ofstream(dir + "/model.json") << meta.dump();
    std::unique_ptr<MotionModel> model = load_motion_model(dir);
    EXPECT_EQ(model->minilm->config().layers, 2);
    EXPECT_EQ(model->minilm->config().intermediate, 64);
    torch::NoGradGuard no_grad;
    // "person walks" -> [CLS] person walks [SEP] = 101 7 19 102 with this vocabulary.
    EXPECT_LT(
        (model->encode_text({"person walks"}) - bert->encode(std::vector<std::vector<int64_t>>{{101, 7, 19, 102}}))
            .abs()
            .max()
            .item<double>(),
        1e-6);
    SampleOptions o;
    o.frames = 8;
    o.sampler = Sampler::ddim;
    o.steps = 2;
    const std::vector<FeatureMatrix> motions = sample_motions(*model, {"a person walks", "person"}, o);
    ASSERT_EQ(motions.size(), 2u);
    EXPECT_TRUE(motions[0].allFinite());

    meta["mdm"]["text_dim"] = 24;
    std::ofstream(dir + "/model.json") << meta.dump();
    try {
        load_motion_model(dir);
        FAIL() << "a text width other than mdm.text_dim was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("mdm.text_dim"), std::string::npos) << e.what();
    }
}
