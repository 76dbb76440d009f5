// CLIP's BPE tokenizer on a hand-made merges file (expected ids worked out from the algorithm: a byte's id is
// its place in the byte table, + 256 with </w>; merge r is id 512 + r), and CLIP's text tower on random weights:
// shapes, the causal mask, end-of-text pooling, key names and their handling, and a model folder that pairs an
// MDM with CLIP.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/npy.hpp"
#include "core/safetensors.hpp"
#include "diffusion/text_to_motion.hpp"
#include "test_util.hpp"
#include "text/clip_bpe.hpp"
#include "text/nn/clip_text_encoder.hpp"

using namespace t2imu;

namespace {

const char* const kMerges = "#version: 0.2\nh e\nl l\nhe ll\nhell o</w>\nw a\nl k\nwa lk\nwalk s</w>\n' s</w>\n";
constexpr int64_t kSot = 521, kEot = 522;  // 512 + 9 merges, then the two special tokens

std::string write_merges(const std::string& dir, bool gzip) {
    const std::string path = dir + (gzip ? "/merges.txt.gz" : "/merges.txt");
    gzFile f = gzopen(path.c_str(), gzip ? "wb" : "wbT");  // T: written through uncompressed
    gzwrite(f, kMerges, static_cast<unsigned>(std::strlen(kMerges)));
    gzclose(f);
    return path;
}

const ClipBpeTokenizer& tokenizer() {
    static const ClipBpeTokenizer t =
        ClipBpeTokenizer::from_merges_file(write_merges(test::scratch_dir("clip-bpe"), true));
    return t;
}

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST(ClipBpe, VocabularyOrderFollowsTheByteTableThenMergesThenSpecials) {
    const ClipBpeTokenizer& t = tokenizer();
    EXPECT_EQ(t.vocab_size(), 523u);
    EXPECT_EQ(t.token(0), "!");
    EXPECT_EQ(t.token(93), "~");
    EXPECT_EQ(t.token(94), "\u00A1");        // byte 161, the first printable Latin-1 byte
    EXPECT_EQ(t.token(188), "\u0100");       // byte 0, the first non-printable one
    EXPECT_EQ(t.token(188 + 32), "\u0120");  // the space byte
    EXPECT_EQ(t.token(223), "\u0123");       // byte 0x81
    EXPECT_EQ(t.token(256), "!</w>");
    EXPECT_EQ(t.token(512), "he");
    EXPECT_EQ(t.token(520), "'s</w>");
    EXPECT_EQ(t.sot(), kSot);
    EXPECT_EQ(t.eot(), kEot);
    EXPECT_EQ(t.token(kSot), "<|startoftext|>");
    EXPECT_THROW(t.token(523), Error);
}

TEST(ClipBpe, MergesByRank) {
    const ClipBpeTokenizer& t = tokenizer();
    // h e l l o</w> -> he l l o</w> -> he ll o</w> -> hell o</w> -> hello</w>
    EXPECT_EQ(t.bpe("hello"), (std::vector<std::string>{"hello</w>"}));
    EXPECT_EQ(t.encode("Hello"), (std::vector<int64_t>{515}));
    // "he" ends the word: its pair is (h, e</w>), which no merge names.
    EXPECT_EQ(t.bpe("he"), (std::vector<std::string>{"h", "e</w>"}));
    // a</w>; p e r s o n</w> (no merge); walks</w>; s l o w l y</w>
    EXPECT_EQ(t.encode("  A person   WALKS\tslowly "),
              (std::vector<int64_t>{320, 79, 68, 81, 82, 78, 333, 519, 82, 75, 78, 86, 75, 344}));
    EXPECT_EQ(t.encode("He's walking"), (std::vector<int64_t>{71, 324, 520, 518, 72, 77, 326}));
    EXPECT_EQ(t.encode("he\u2019s"), (std::vector<int64_t>{71, 324, 520}));  // ftfy's quote uncurling
    EXPECT_EQ(t.encode("walks 10 steps, 2x"),
              (std::vector<int64_t>{519, 272, 271, 82, 83, 68, 79, 338, 267, 273, 343}));
    EXPECT_EQ(t.encode("a<|endoftext|>b"), (std::vector<int64_t>{320, kEot, 321}));
    EXPECT_TRUE(t.encode(" \t\n").empty());
}

TEST(ClipBpe, NonAsciiGoesThroughTheByteTable) {
    const ClipBpeTokenizer& t = tokenizer();
    // é = C3 A9: both printable Latin-1 bytes (ids 106 + 21 and 94 + 8, the last + 256).
    EXPECT_EQ(t.encode("caf\u00E9"), (std::vector<int64_t>{66, 64, 69, 127, 358}));
    EXPECT_EQ(t.encode("CAF\u00C9"), t.encode("caf\u00E9"));
    // ā = C4 81: 0x81 is not printable, it stands as U+0123 (id 188 + 35), + 256 as the word's end.
    EXPECT_EQ(t.encode("\u0101"), (std::vector<int64_t>{128, 479}));
    EXPECT_EQ(t.encode("\u03A9"), (std::vector<int64_t>{139, 487}));  // Ω lower-cases to ω = CF 89
}

TEST(ClipBpe, SplitsLikeClipsPattern) {
    using V = std::vector<std::string>;
    EXPECT_EQ(ClipBpeTokenizer::split("don't they're i'm we'll you'd i've"),
              (V{"don", "'t", "they", "'re", "i", "'m", "we", "'ll", "you", "'d", "i", "'ve"}));
    EXPECT_EQ(ClipBpeTokenizer::split("rock'n'roll"), (V{"rock", "'", "n", "'", "roll"}));
    EXPECT_EQ(ClipBpeTokenizer::split("walks 10 steps, 2x"), (V{"walks", "1", "0", "steps", ",", "2", "x"}));
    EXPECT_EQ(ClipBpeTokenizer::split("3.5m !!? a-b"), (V{"3", ".", "5", "m", "!!?", "a", "-", "b"}));
    EXPECT_EQ(ClipBpeTokenizer::split("!<|endoftext|>"), (V{"!<|", "endoftext", "|>"}));
    EXPECT_EQ(ClipBpeTokenizer::split("x\u00B2\u00BD \u0663"),
              (V{"x", "\u00B2", "\u00BD", "\u0663"}));  // numbers: one each
    EXPECT_EQ(ClipBpeTokenizer::split("na\u00EFve \u03C9mega"), (V{"na\u00EFve", "\u03C9mega"}));
    // Letters inside UnicodeData.txt's First/Last ranges (CJK ideographs, Hangul syllables); U+00D7 is a symbol.
    EXPECT_EQ(ClipBpeTokenizer::split("\u8D70\u8DEF\uAC00 3\u00D7a"), (V{"\u8D70\u8DEF\uAC00", "3", "\u00D7", "a"}));
    EXPECT_EQ(ClipBpeTokenizer::clean("  Two\u00A0 WORDS\n"), "two words");
}

TEST(ClipBpe, LowerCasesAsPythonDoes) {
    // Latin-1, a stride-2 run (A-macron), a title-case digraph (Dz with caron), capital sharp s, the Kelvin sign.
    EXPECT_EQ(ClipBpeTokenizer::clean("\u00C0\u0100\u0101\u01C5\u1E9E\u212A"), "\u00E0\u0101\u0101\u01C6\u00DFk");
    EXPECT_EQ(ClipBpeTokenizer::clean("\u0130"), "i\u0307");  // capital I with dot: two code points
    // Capital sigma: final at a word's end, medial elsewhere (Python: "ΟΔΟΣ ΣΑ Σ ΑΣ.".lower()).
    EXPECT_EQ(ClipBpeTokenizer::clean("\u039F\u0394\u039F\u03A3 \u03A3\u0391 \u03A3 \u0391\u03A3."),
              "\u03BF\u03B4\u03BF\u03C2 \u03C3\u03B1 \u03C3 \u03B1\u03C2.");
    EXPECT_EQ(ClipBpeTokenizer::clean("\u201CHe\u2018s\u201D"), "\"he's\"");  // ftfy's quote uncurling
}

TEST(ClipBpe, TokenizePadsTruncatesAndRefuses) {
    const ClipBpeTokenizer& t = tokenizer();
    const std::vector<int64_t> ids = t.tokenize("hello");
    ASSERT_EQ(ids.size(), 77u);
    EXPECT_EQ((std::vector<int64_t>(ids.begin(), ids.begin() + 3)), (std::vector<int64_t>{kSot, 515, kEot}));
    EXPECT_EQ(std::count(ids.begin() + 3, ids.end(), 0), 74);
    EXPECT_EQ(t.tokenize("hello hello hello", 5), (std::vector<int64_t>{kSot, 515, 515, 515, kEot}));  // fits exactly
    EXPECT_EQ(t.tokenize("hello hello hello", 4, true), (std::vector<int64_t>{kSot, 515, 515, kEot}));
    EXPECT_THROW(t.tokenize("hello hello hello", 4), Error);
    // MDM's humanml/kit context: 22 tokens, the last EOT, whatever the length of the caption.
    std::string long_caption;
    for (int i = 0; i < 30; ++i) long_caption += "walks ";
    const std::vector<int64_t> mdm = t.tokenize(long_caption, 22, true);
    EXPECT_EQ(mdm.size(), 22u);
    EXPECT_EQ(mdm.front(), kSot);
    EXPECT_EQ(mdm.back(), kEot);
    EXPECT_EQ(mdm[20], 519);
}

TEST(ClipBpe, ReadsGzipAndPlainMergesAndRefusesBadLines) {
    const std::string dir = test::scratch_dir("clip-merges");
    const ClipBpeTokenizer plain = ClipBpeTokenizer::from_merges_file(write_merges(dir, false));
    EXPECT_EQ(plain.encode("He's walking"), tokenizer().encode("He's walking"));
    EXPECT_EQ(ClipBpeTokenizer::from_merges_file(write_merges(dir, true), 3).vocab_size(), 512u + 3 + 2);  // CLIP's cap
    std::ofstream(dir + "/bad.txt") << "#version: 0.2\nh e\nl l x\n";
    EXPECT_NE(message_of([&] { ClipBpeTokenizer::from_merges_file(dir + "/bad.txt"); }).find("line 3"),
              std::string::npos);
    std::ofstream(dir + "/gap.txt") << "#version: 0.2\nh e\n\nl l\n";
    EXPECT_THROW(ClipBpeTokenizer::from_merges_file(dir + "/gap.txt"), Error);
    EXPECT_THROW(ClipBpeTokenizer::from_merges_file(dir + "/absent.txt.gz"), Error);
}

namespace {

ClipTextConfig tiny() {
    ClipTextConfig c;
    c.vocab_size = 523;
    c.context_length = 16;
    c.width = 32;
    c.heads = 4;
    c.layers = 2;
    c.embed_dim = 24;
    c.mdm_text_tokens = 6;
    return c;
}

ClipTextEncoder random_clip(uint64_t seed, int64_t heads = 4) {
    torch::manual_seed(seed);
    ClipTextConfig c = tiny();
    c.heads = heads;
    ClipTextEncoder m(c);
    torch::NoGradGuard no_grad;
    for (auto& p : m->parameters()) p.normal_(0, 0.2);  // LayerNorm gains and biases too
    m->eval();
    return m;
}

NdArray to_array(const torch::Tensor& t) {
    const torch::Tensor c = t.detach().to(torch::kFloat).contiguous();
    return NdArray::from(std::vector<float>(c.data_ptr<float>(), c.data_ptr<float>() + c.numel()),
                         std::vector<int64_t>(c.sizes().begin(), c.sizes().end()));
}

SafeTensors openai_state(ClipTextEncoder& m, const std::string& prefix) {
    SafeTensors st;
    for (const auto& p : m->named_parameters()) st.tensors[prefix + p.key()] = to_array(p.value());
    return st;
}

SafeTensors hugging_face_state(ClipTextEncoder& m) {
    SafeTensors st;
    const auto params = m->named_parameters();
    st.tensors["text_model.embeddings.token_embedding.weight"] = to_array(params["token_embedding.weight"]);
    st.tensors["text_model.embeddings.position_embedding.weight"] = to_array(params["positional_embedding"]);
    st.tensors["text_model.final_layer_norm.weight"] = to_array(params["ln_final.weight"]);
    st.tensors["text_model.final_layer_norm.bias"] = to_array(params["ln_final.bias"]);
    st.tensors["text_projection.weight"] = to_array(params["text_projection"].t());
    for (int i = 0; i < 2; ++i) {
        const std::string o = "transformer.resblocks." + std::to_string(i) + ".",
                          h = "text_model.encoder.layers." + std::to_string(i) + ".";
        const std::vector<torch::Tensor> w = params[o + "attn.in_proj_weight"].chunk(3, 0),
                                         b = params[o + "attn.in_proj_bias"].chunk(3, 0);
        const char* qkv[] = {"q", "k", "v"};
        for (int k = 0; k < 3; ++k) {
            st.tensors[h + "self_attn." + qkv[k] + "_proj.weight"] = to_array(w[static_cast<size_t>(k)]);
            st.tensors[h + "self_attn." + qkv[k] + "_proj.bias"] = to_array(b[static_cast<size_t>(k)]);
        }
        for (const char* s : {"weight", "bias"}) {
            st.tensors[h + "self_attn.out_proj." + s] = to_array(params[o + "attn.out_proj." + s]);
            st.tensors[h + "layer_norm1." + s] = to_array(params[o + "ln_1." + s]);
            st.tensors[h + "layer_norm2." + s] = to_array(params[o + "ln_2." + s]);
            st.tensors[h + "mlp.fc1." + s] = to_array(params[o + "mlp.c_fc." + s]);
            st.tensors[h + "mlp.fc2." + s] = to_array(params[o + "mlp.c_proj." + s]);
        }
    }
    st.tensors["text_model.embeddings.position_ids"] = NdArray::from(std::vector<int64_t>(16, 0), {1, 16});
    st.tensors["vision_model.post_layernorm.weight"] = NdArray::from(std::vector<float>(8, 1.f), {8});
    st.tensors["logit_scale"] = NdArray::from(std::vector<float>{4.6f}, {});
    return st;
}

// Rows: SOT, tokens, EOT, zero padding to 16.
torch::Tensor ids_of(const std::vector<std::vector<int64_t>>& rows) {
    torch::Tensor t = torch::zeros({static_cast<int64_t>(rows.size()), 16}, torch::kInt64);
    for (size_t b = 0; b < rows.size(); ++b)
        for (size_t k = 0; k < rows[b].size(); ++k) t[static_cast<int64_t>(b)][static_cast<int64_t>(k)] = rows[b][k];
    return t;
}

double max_diff(const torch::Tensor& a, const torch::Tensor& b) { return (a - b).abs().max().item<double>(); }

}  // namespace

TEST(ClipTextEncoder, OpenAiKeyNames) {
    ClipTextEncoder m(tiny());
    const auto params = m->named_parameters();
    for (const char* key : {"token_embedding.weight", "positional_embedding", "transformer.resblocks.0.ln_1.weight",
                            "transformer.resblocks.0.attn.in_proj_weight", "transformer.resblocks.1.attn.in_proj_bias",
                            "transformer.resblocks.1.attn.out_proj.weight", "transformer.resblocks.0.ln_2.bias",
                            "transformer.resblocks.1.mlp.c_fc.weight", "transformer.resblocks.0.mlp.c_proj.bias",
                            "ln_final.weight", "text_projection"})
        EXPECT_TRUE(params.contains(key)) << key;
    EXPECT_EQ(params.size(), 2u + 2 * 12u + 3u);
    EXPECT_EQ(params["transformer.resblocks.0.attn.in_proj_weight"].sizes(), (std::vector<int64_t>{96, 32}));
    EXPECT_EQ(params["transformer.resblocks.0.mlp.c_fc.weight"].sizes(), (std::vector<int64_t>{128, 32}));
    EXPECT_EQ(params["text_projection"].sizes(), (std::vector<int64_t>{32, 24}));
    for (const auto& p : m->parameters()) EXPECT_FALSE(p.requires_grad());  // frozen, as in MDM
}

TEST(ClipTextEncoder, CausalMaskAndEndOfTextPooling) {
    ClipTextEncoder m = random_clip(5);
    torch::NoGradGuard no_grad;
    const torch::Tensor ids = ids_of({{kSot, 515, 79, 68, kEot}, {kSot, 519, 82, 75, 78, 86, 75, 344, kEot}});
    const torch::Tensor out = m->forward(ids);
    EXPECT_EQ(out.sizes(), (std::vector<int64_t>{2, 24}));
    // Pooling: the projected final state at the EOT position (4 and 8).
    const torch::Tensor h = m->hidden_states(ids);
    const torch::Tensor P = m->named_parameters()["text_projection"];
    EXPECT_LT(max_diff(out[0], h[0][4].matmul(P)), 1e-6);
    EXPECT_LT(max_diff(out[1], h[1][8].matmul(P)), 1e-6);
    EXPECT_GT(max_diff(out[0], h[0][3].matmul(P)), 1e-3);
    // Tokens after EOT (the padding) are invisible to it...
    torch::Tensor padded = ids.clone();
    padded[0][7] = 300;
    padded[1][12] = 5;
    EXPECT_LT(max_diff(m->forward(padded), out), 1e-6);
    // ...and so is cutting them off: MDM's 22 tokens padded to 77 encode as the 22 alone.
    EXPECT_LT(max_diff(m->forward(ids.narrow(1, 0, 9)), out), 1e-5);
    // A token before EOT is not.
    torch::Tensor changed = ids.clone();
    changed[0][2] = 80;
    const torch::Tensor moved = m->forward(changed);
    EXPECT_GT(max_diff(moved[0], out[0]), 1e-3);
    EXPECT_LT(max_diff(moved[1], out[1]), 1e-6);  // rows are independent
    EXPECT_THROW(m->forward(torch::zeros({1, 17}, torch::kInt64)), Error);
}

TEST(ClipTextEncoder, EncodesCaptionsAsMdmDoes) {
    ClipTextEncoder m = random_clip(6);
    torch::NoGradGuard no_grad;
    EXPECT_THROW(m->encode({"hello"}), Error);  // no tokenizer yet
    m->set_tokenizer(std::make_shared<const ClipBpeTokenizer>(tokenizer()));
    const std::vector<std::string> captions = {"Hello", "He's walking walks walks walks walks"};
    std::vector<std::vector<int64_t>> rows;
    for (const std::string& c : captions)
        rows.push_back(tokenizer().tokenize(c, 6, true));  // mdm_text_tokens, then zeros to 16
    EXPECT_EQ(rows[1].back(), kEot);
    EXPECT_LT(max_diff(m->encode(captions), m->forward(ids_of(rows))), 1e-6);
    ClipTextConfig other = tiny();
    other.vocab_size = 600;
    ClipTextEncoder wrong(other);
    EXPECT_THROW(wrong->set_tokenizer(std::make_shared<const ClipBpeTokenizer>(tokenizer())), Error);
}

TEST(ClipTextEncoder, SafetensorsRoundTripUnderOpenAiAndMdmNames) {
    ClipTextEncoder source = random_clip(7), target = random_clip(8);
    torch::NoGradGuard no_grad;
    const std::string dir = test::scratch_dir("clip-weights");
    const torch::Tensor ids = ids_of({{kSot, 515, 79, kEot}, {kSot, 519, 82, 75, 78, kEot}});
    ASSERT_GT(max_diff(source->forward(ids), target->forward(ids)), 1e-3);
    // CLIP's whole state dict: the image tower and logit_scale are ignored.
    SafeTensors full = openai_state(source, "");
    full.tensors["visual.conv1.weight"] = NdArray::from(std::vector<float>(12, 0.5f), {3, 4});
    full.tensors["logit_scale"] = NdArray::from(std::vector<float>{4.6f}, {});
    write_safetensors(dir + "/openai.safetensors", full);
    load_clip_text_weights(target, dir + "/openai.safetensors");
    EXPECT_LT(max_diff(source->forward(ids), target->forward(ids)), 1e-6);
    const ClipTextConfig read = read_clip_text_config(dir + "/openai.safetensors");
    EXPECT_EQ(read.vocab_size, 523);
    EXPECT_EQ(read.width, 32);
    EXPECT_EQ(read.context_length, 16);
    EXPECT_EQ(read.layers, 2);
    EXPECT_EQ(read.embed_dim, 24);
    EXPECT_EQ(read.heads, 1);  // CLIP's 64-wide heads; ViT-B/32's 512 gives 8
    // An MDM state dict with its frozen CLIP under clip_model.: MDM's own keys are left alone.
    ClipTextEncoder third = random_clip(9);
    SafeTensors mdm = openai_state(source, "clip_model.");
    mdm.tensors["embed_text.weight"] = NdArray::from(std::vector<float>(24 * 4, 0.1f), {4, 24});
    mdm.tensors["clip_model.visual.proj"] = NdArray::from(std::vector<float>(4, 0.1f), {2, 2});
    write_safetensors(dir + "/mdm.safetensors", mdm);
    load_clip_text_weights(third, dir + "/mdm.safetensors");
    EXPECT_LT(max_diff(source->forward(ids), third->forward(ids)), 1e-6);
    EXPECT_EQ(read_clip_text_config(dir + "/mdm.safetensors").layers, 2);
}

TEST(ClipTextEncoder, HuggingFaceNames) {
    ClipTextEncoder source = random_clip(10), target = random_clip(11);
    torch::NoGradGuard no_grad;
    const std::string dir = test::scratch_dir("clip-hf");
    SafeTensors st = hugging_face_state(source);
    write_safetensors(dir + "/hf.safetensors", st);
    load_clip_text_weights(target, dir + "/hf.safetensors");
    const torch::Tensor ids = ids_of({{kSot, 515, 79, 68, 81, kEot}});
    EXPECT_LT(max_diff(source->forward(ids), target->forward(ids)), 1e-6);
    EXPECT_EQ(read_clip_text_config(dir + "/hf.safetensors").embed_dim, 24);
    EXPECT_EQ(read_clip_text_config(dir + "/hf.safetensors").layers, 2);
    st.tensors.erase("text_model.encoder.layers.1.self_attn.k_proj.weight");
    write_safetensors(dir + "/hf-missing.safetensors", st);
    const std::string msg = message_of([&] { load_clip_text_weights(target, dir + "/hf-missing.safetensors"); });
    EXPECT_NE(msg.find("text_model.encoder.layers.1.self_attn.k_proj.weight"), std::string::npos) << msg;
    EXPECT_NE(msg.find("missing"), std::string::npos) << msg;
}

TEST(ClipTextEncoder, RefusesMissingUnexpectedAndMisShapedKeys) {
    ClipTextEncoder source = random_clip(12), target = random_clip(13);
    const std::string dir = test::scratch_dir("clip-keys");
    SafeTensors missing = openai_state(source, "");
    missing.tensors.erase("transformer.resblocks.1.mlp.c_proj.weight");
    write_safetensors(dir + "/missing.safetensors", missing);
    std::string msg = message_of([&] { load_clip_text_weights(target, dir + "/missing.safetensors"); });
    EXPECT_NE(msg.find("transformer.resblocks.1.mlp.c_proj.weight"), std::string::npos) << msg;
    EXPECT_NE(msg.find("[32, 128]"), std::string::npos) << msg;

    SafeTensors extra = openai_state(source, "clip_model.");
    extra.tensors["clip_model.transformer.resblocks.2.ln_1.weight"] = NdArray::from(std::vector<float>(32, 1.f), {32});
    write_safetensors(dir + "/extra.safetensors", extra);
    msg = message_of([&] { load_clip_text_weights(target, dir + "/extra.safetensors"); });
    EXPECT_NE(msg.find("clip_model.transformer.resblocks.2.ln_1.weight"), std::string::npos) << msg;
    EXPECT_NE(msg.find("unexpected"), std::string::npos) << msg;

    SafeTensors shape = openai_state(source, "");
    shape.tensors["text_projection"] = NdArray::from(std::vector<float>(32 * 16, 0.f), {32, 16});
    write_safetensors(dir + "/shape.safetensors", shape);
    msg = message_of([&] { load_clip_text_weights(target, dir + "/shape.safetensors"); });
    EXPECT_NE(msg.find("text_projection"), std::string::npos) << msg;
    EXPECT_NE(msg.find("[32, 24]"), std::string::npos) << msg;
    EXPECT_NE(msg.find("(32, 16)"), std::string::npos) << msg;

    SafeTensors none;
    none.tensors["embed_text.weight"] = NdArray::from(std::vector<float>(4, 0.f), {2, 2});
    write_safetensors(dir + "/none.safetensors", none);
    EXPECT_NE(
        message_of([&] { load_clip_text_weights(target, dir + "/none.safetensors"); }).find("token_embedding.weight"),
        std::string::npos);
}

TEST(ClipTextEncoder, ModelFolderPairsAnMdmWithClip) {
    const std::string dir = test::scratch_dir("clip-model");
    ClipTextEncoder clip = random_clip(14);
    MdmConfig mc;
    mc.latent_dim = 32;
    mc.ff_size = 64;
    mc.num_layers = 2;
    mc.num_heads = 2;
    mc.dropout = 0.0;
    mc.text_dim = 24;
    torch::manual_seed(15);
    Mdm mdm(mc);
    // One file, as an official MDM state dict with its CLIP: MDM's keys and clip_model.*.
    SafeTensors st = openai_state(clip, "clip_model.");
    for (const auto& p : mdm->named_parameters()) st.tensors[p.key()] = to_array(p.value());
    write_safetensors(dir + "/weights.safetensors", st);
    write_merges(dir, true);
    write_npy(dir + "/Mean.npy", NdArray::from(std::vector<double>(263, 0.0), {263}));
    write_npy(dir + "/Std.npy", NdArray::from(std::vector<double>(263, 1.0), {263}));
    nlohmann::json meta = {
        {"mdm",
         {{"latent_dim", 32},
          {"ff_size", 64},
          {"num_layers", 2},
          {"num_heads", 2},
          {"dropout", 0.0},
          {"text_dim", 24},
          {"mask_frames", false}}},
        {"text_encoder",
         {{"kind", "clip"}, {"weights", "weights.safetensors"}, {"merges", "merges.txt.gz"}, {"text_tokens", 6}}},
        {"diffusion", {{"steps", 10}}}};
    std::ofstream(dir + "/model.json") << meta.dump();
    // The tiny tower's width is 32: read_clip_text_config's 64-wide heads give 1 head, as CLIP would build it.
    ClipTextConfig one_head = tiny();
    one_head.heads = 1;
    ClipTextEncoder reference(one_head);
    load_clip_text_weights(reference, dir + "/weights.safetensors");
    reference->set_tokenizer(std::make_shared<const ClipBpeTokenizer>(tokenizer()));

    std::unique_ptr<MotionModel> model = load_motion_model(dir);
    torch::NoGradGuard no_grad;
    const std::vector<std::string> prompts = {"a person walks", "He's walking"};
    EXPECT_LT(max_diff(model->encode_text(prompts), reference->encode(prompts)), 1e-6);
    SampleOptions o;
    o.frames = 8;
    o.sampler = Sampler::ddim;
    o.steps = 2;
    const std::vector<FeatureMatrix> motions = sample_motions(*model, prompts, o);
    ASSERT_EQ(motions.size(), 2u);
    EXPECT_EQ(motions[0].rows(), 8);
    EXPECT_TRUE(motions[0].allFinite());

    meta["text_encoder"]["kind"] = "word2vec";
    std::ofstream(dir + "/model.json") << meta.dump();
    EXPECT_NE(message_of([&] { load_motion_model(dir); }).find("glove_transformer, clip or minilm"), std::string::npos);
    meta["text_encoder"]["kind"] = "clip";
    meta["text_encoder"]["merges"] = "absent.txt.gz";
    std::ofstream(dir + "/model.json") << meta.dump();
    EXPECT_NE(message_of([&] { load_motion_model(dir); }).find("text_encoder.merges"), std::string::npos);
    meta["text_encoder"]["merges"] = "merges.txt.gz";
    meta["mdm"]["text_dim"] = 16;
    std::ofstream(dir + "/model.json") << meta.dump();
    EXPECT_NE(message_of([&] { load_motion_model(dir); }).find("text_projection"), std::string::npos);
}

TEST(ClipTextEncoder, ModelFolderWithCLIPInItsOwnFile) {
    const std::string dir = test::scratch_dir("clip-model-apart");
    ClipTextEncoder clip = random_clip(16, 1);  // one head: what read_clip_text_config builds for width 32
    MdmConfig mc;
    mc.latent_dim = 32;
    mc.ff_size = 64;
    mc.num_layers = 1;
    mc.num_heads = 2;
    mc.text_dim = 24;
    Mdm mdm(mc);
    write_safetensors(dir + "/clip.safetensors", openai_state(clip, ""));
    SafeTensors st;
    for (const auto& p : mdm->named_parameters()) st.tensors[p.key()] = to_array(p.value());
    write_safetensors(dir + "/weights.safetensors", st);
    write_merges(dir, false);
    write_npy(dir + "/Mean.npy", NdArray::from(std::vector<double>(263, 0.0), {263}));
    write_npy(dir + "/Std.npy", NdArray::from(std::vector<double>(263, 1.0), {263}));
    const nlohmann::json meta = {
        {"mdm",
         {{"latent_dim", 32},
          {"ff_size", 64},
          {"num_layers", 1},
          {"num_heads", 2},
          {"dropout", 0.1},
          {"text_dim", 24},
          {"mask_frames", false}}},
        {"text_encoder", {{"kind", "clip"}, {"weights", dir + "/clip.safetensors"}, {"merges", "merges.txt"}}},
        {"diffusion", {{"steps", 10}}}};
    std::ofstream(dir + "/model.json") << meta.dump();
    std::unique_ptr<MotionModel> model = load_motion_model(dir);
    EXPECT_EQ(model->clip->config().mdm_text_tokens, 22);  // MDM's HumanML3D context when model.json names none
    torch::NoGradGuard no_grad;
    const torch::Tensor ids = ids_of({{kSot, 320, 79, 68, 81, 82, 78, 333, 519, kEot}});  // "a person walks"
    EXPECT_LT(max_diff(model->encode_text({"a person walks"}), clip->forward(ids)), 1e-6);
    // CLIP lives elsewhere, so a clip_model.* key in the MDM's file is a stray one.
    st.tensors["clip_model.ln_final.weight"] = NdArray::from(std::vector<float>(32, 1.f), {32});
    write_safetensors(dir + "/weights.safetensors", st);
    const std::string msg = message_of([&] { load_motion_model(dir); });
    EXPECT_NE(msg.find("clip_model.ln_final.weight"), std::string::npos) << msg;
    EXPECT_NE(msg.find("unexpected"), std::string::npos) << msg;
}
