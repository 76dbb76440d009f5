// Text: BERT's WordPiece against the reference token ids, the GloVe tokenizer and vocabulary file, SIF.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "test_util.hpp"
#include "text/sentence_similarity.hpp"
#include "text/utf8.hpp"
#include "text/word_tokenizer.hpp"
#include "text/wordpiece.hpp"

using namespace t2imu;

TEST(WordPiece, ReproducesTheReferenceTokenIds) {
    std::string vocab, sentences;
    SHARED_OR_SKIP(vocab, "reference/minilm/assets/vocab.txt");
    SHARED_OR_SKIP(sentences, "reference/minilm/tokens/sentences.json");
    const WordPieceTokenizer tok = WordPieceTokenizer::from_vocab_file(vocab);
    const nlohmann::json ref = nlohmann::json::parse(read_file_text(sentences));
    const std::vector<int64_t> ids = read_npy(test::shared_path("reference/minilm/tokens/input_ids.npy")).to<int64_t>();
    const size_t width = ids.size() / ref.size();
    ASSERT_EQ(ref.size(), 22u);
    for (size_t s = 0; s < ref.size(); ++s) {
        const std::string text = ref[s]["text"];
        EXPECT_EQ(tok.wordpieces(text), ref[s]["tokens"].get<std::vector<std::string>>()) << text;
        const std::vector<int64_t> got = tok.encode(text);
        EXPECT_EQ(got, ref[s]["input_ids"].get<std::vector<int64_t>>()) << text;
        for (size_t k = 0; k < width; ++k)
            EXPECT_EQ(k < got.size() ? got[k] : 0, ids[s * width + k]) << text;  // right-padded with [PAD] = 0
    }
    EXPECT_EQ(tok.encode("Hello, world!"), (std::vector<int64_t>{101, 7592, 1010, 2088, 999, 102}));
    // A word over 100 characters is one [UNK]: [CLS] [UNK] b [SEP].
    EXPECT_EQ(tok.encode(std::string(600, 'a') + " b", 8), (std::vector<int64_t>{101, 100, 1038, 102}));
    EXPECT_EQ(tok.encode("walk walk walk walk", 4).size(), 4u);  // truncated, [SEP] kept
}

TEST(Utf8, FirstInvalidByteAsNlohmannJsonJudgesIt) {
    EXPECT_EQ(first_invalid_utf8("a man walks \xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80"), std::string::npos);
    EXPECT_EQ(first_invalid_utf8("walks \xff"), 6u);
    EXPECT_EQ(first_invalid_utf8("ab\xC3"), 2u);            // truncated
    EXPECT_EQ(first_invalid_utf8("\xC0\xAF"), 0u);          // overlong '/'
    EXPECT_EQ(first_invalid_utf8("x\xE0\x80\xAF"), 1u);     // overlong, three bytes
    EXPECT_EQ(first_invalid_utf8("\xED\xA0\x80"), 0u);      // a surrogate
    EXPECT_EQ(first_invalid_utf8("\xF4\x90\x80\x80"), 0u);  // above U+10FFFF
    for (const std::string bad : {"walks \xff", "ab\xC3", "\xED\xA0\x80"})
        EXPECT_THROW(nlohmann::json(bad).dump(), nlohmann::json::type_error) << bad;
}

TEST(WordTokenizer, SplitsLikeGloVesVocabulary) {
    EXPECT_EQ(split_words("A person's counter-clockwise turn, then STOPS."),
              (std::vector<std::string>{"a", "person's", "counter-clockwise", "turn", ",", "then", "stops", "."}));
    EXPECT_EQ(split_words("  -jump- 'now'"), (std::vector<std::string>{"-", "jump", "-", "'", "now", "'"}));
    const WordVectors v({"walk", "person", "counter", "clockwise", "jump", "."}, std::vector<float>(6 * 100, 0.5f));
    // walk (walked -> walk), person's -> person, counter-clockwise -> its parts, jumps -> jump, unknown -> -1.
    EXPECT_EQ(word_indices("Walked person's counter-clockwise jumps zzyzx.", v),
              (std::vector<int>{0, 1, 2, 3, 4, -1, 5}));
}

TEST(WordVectors, FileRoundTripAndZipfProbabilities) {
    std::vector<float> values(3 * 100);
    for (size_t i = 0; i < values.size(); ++i)
        values[i] = static_cast<float>(std::sin(0.37 * static_cast<double>(i)) * 4);
    const WordVectors v({"the", "walks", "é"}, values);
    const std::string path = test::scratch_dir("word_vectors") + "/v.safetensors";
    v.save(path);
    const WordVectors back = WordVectors::load(path);
    ASSERT_EQ(back.size(), 3);
    EXPECT_EQ(back.word(2), "é");
    EXPECT_EQ(back.index_of("walks"), 1);
    for (int i = 0; i < 3; ++i)
        for (int d = 0; d < 100; ++d)
            EXPECT_NEAR(back.vector(i)[d], values[static_cast<size_t>(i * 100 + d)], 4.0 / 1024);  // float16
    EXPECT_NEAR(back.probability(0) + back.probability(1) + back.probability(2), 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(back.probability(0) / back.probability(1), 2.0);
    EXPECT_THROW(WordVectors({"a"}, std::vector<float>(99)), Error);
}

TEST(SifEncoder, WeightsRareWordsAndRemovesTheCommonComponent) {
    // Three words along the axes; "the" is the most frequent, so it weighs least.
    std::vector<float> values(3 * 100, 0.f);
    values[0] = 1;        // the   -> e0
    values[100 + 1] = 1;  // walk  -> e1
    values[200 + 2] = 1;  // run   -> e2
    const WordVectors v({"the", "walk", "run"}, values);
    SifEncoder sif(v);
    const Eigen::VectorXd e = sif.embed("the walk");
    const double w_the = 1e-3 / (1e-3 + v.probability(0)), w_walk = 1e-3 / (1e-3 + v.probability(1));
    EXPECT_NEAR(e[0], w_the / 2, 1e-12);
    EXPECT_NEAR(e[1], w_walk / 2, 1e-12);
    EXPECT_LT(e[0], e[1]);
    EXPECT_DOUBLE_EQ(cosine_similarity(sif.embed("walk"), sif.embed("walk")), 1.0);
    EXPECT_DOUBLE_EQ(cosine_similarity(sif.embed("walk"), sif.embed("run")), 0.0);
    EXPECT_EQ(sif.embed("xyz").norm(), 0.0);  // nothing known
    sif.fit_common_component({"walk", "walk run", "walk the", "walk walk"});
    EXPECT_GT(std::fabs(sif.common_component()[1]), 0.95);                       // "walk" is what the corpus shares
    EXPECT_NEAR(sif.embed("walk run").dot(sif.common_component()), 0.0, 1e-15);  // projected out
}

TEST(SifEncoder, NearestSentenceIsTheMostSimilarCaption) {
    std::vector<float> values(4 * 100, 0.f);
    values[0] = 1;           // the  -> e0
    values[100 + 1] = 1;     // walk -> e1
    values[200 + 2] = 1;     // run  -> e2
    values[300 + 1] = 0.6f;  // jog  -> 0.6 e1 + 0.8 e2: nearer run than walk
    values[300 + 2] = 0.8f;
    const WordVectors v({"the", "walk", "run", "jog"}, values);
    const SifEncoder sif(v);
    const std::vector<std::string> corpus = {"the walk", "run", "walk"};
    const std::vector<NearestSentence> n = nearest_sentences(sif, corpus, {"walk", "jog", "run run", "xyz"});
    ASSERT_EQ(n.size(), 4u);
    EXPECT_EQ(n[0].index, 2u);
    EXPECT_DOUBLE_EQ(n[0].similarity, 1.0);
    EXPECT_EQ(n[1].index, 1u);
    EXPECT_NEAR(n[1].similarity, 0.8, 1e-3);  // cos(jog, run), float16-stored vectors
    EXPECT_EQ(n[2].index, 1u);
    EXPECT_EQ(n[3].similarity, 0.0);  // no known word: similar to nothing
    EXPECT_EQ(nearest_sentences(sif, {}, {"walk"})[0].index, 0u);
}

TEST(SifEncoder, GloVeSimilaritiesRankActivitiesSensibly) {
    const std::string vocab = test::source_dir() + "/cache/text/glove-100k.safetensors";
    if (!std::filesystem::exists(vocab))
        GTEST_SKIP() << "cache/text/glove-100k.safetensors absent (scripts/setup.sh makes it)";
    const WordVectors v = WordVectors::load(vocab);
    EXPECT_EQ(v.size(), 100000);
    EXPECT_EQ(v.word(0), "the");
    const SifEncoder sif(v);
    const auto sim = [&](const char* a, const char* b) { return cosine_similarity(sif.embed(a), sif.embed(b)); };
    EXPECT_GT(sim("a person walks forward slowly", "walking"), sim("a person walks forward slowly", "sitting"));
    EXPECT_GT(sim("a person sits down on a chair", "sitting"), sim("a person sits down on a chair", "running"));
    EXPECT_GT(sim("someone dances to music", "dancing"), sim("someone dances to music", "lying"));
}
