// CLIP's tokenizer (Radford et al. 2021; the one MDM feeds its frozen ViT-B/32 text tower): byte-level BPE
// over the merges of `bpe_simple_vocab_16e6.txt.gz`, ids wrapped in <|startoftext|> ... <|endoftext|> and
// zero-padded to a context length.
//
//   clean       collapse every run of whitespace (Python's str.isspace set) to one space, trim, lower-case
//               (Python's str.lower(): unicode_classes.hpp, U+0130 and final sigma). Of CLIP's ftfy +
//               html.unescape pass only ftfy's quote uncurling (U+02BC, U+2018..U+201B -> ', U+201C..U+201F
//               -> ") is applied: mojibake repair, NFC, ligature/width folding and HTML entities are not, so
//               such input can tokenize differently.
//   split       CLIP's pre-tokenisation, left to right, first alternative that matches: the two special
//               tokens written out, the contractions 's 't 're 've 'm 'll 'd, a run of letters (Unicode L*), one
//               number character (N*), a run of anything else but whitespace, letters and numbers.
//   bytes       each piece's UTF-8 bytes become printable characters (GPT-2's byte table: the 188 printable
//               Latin-1 bytes stand for themselves, the other 68 map to U+0100.. in byte order); the last
//               character carries the end-of-word marker </w>.
//   merge       repeatedly join the adjacent pair with the lowest merge rank until no pair has one.
//
// Vocabulary, in id order: the 256 byte characters (printable ones first, in the byte table's order), the
// same with </w>, one entry per merge, <|startoftext|>, <|endoftext|>. The real file yields 49408 ids: only
// its first 48894 merges (after the header line) are used, as CLIP does. The vocabulary is built, not read:
// OpenAI's bpe_simple_vocab_16e6.txt.gz (shipped inside its `clip` package) is the one input. Hugging Face's
// merges.txt for CLIP has the same layout and lines and can be given instead; its vocab.json is the
// vocabulary built here, so it is not needed.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace t2imu {

class ClipBpeTokenizer {
public:
    static constexpr size_t kClipMerges = 49152 - 256 - 2;  // merges CLIP reads from its file
    static constexpr int64_t kContextLength = 77;

    // `path`: the merges file, gzip-compressed (bpe_simple_vocab_16e6.txt.gz) or plain; its first line is a
    // header and is skipped; then one merge "left right" a line, at most `max_merges` of them.
    static ClipBpeTokenizer from_merges_file(const std::string& path, size_t max_merges = kClipMerges);
    explicit ClipBpeTokenizer(const std::vector<std::pair<std::string, std::string>>& merges);

    static std::string clean(const std::string& text);
    static std::vector<std::string> split(const std::string& cleaned);  // pre-tokens, UTF-8
    std::vector<std::string> bpe(const std::string& piece) const;       // one pre-token -> vocabulary entries
    std::vector<int64_t> encode(const std::string& text) const;         // clean, split, bpe; no SOT/EOT

    // clip.tokenize for one text: SOT ids EOT, then zeros up to `context_length`. Longer than that: with
    // `truncate` cut to context_length with EOT last, else an Error.
    std::vector<int64_t> tokenize(const std::string& text, int64_t context_length = kContextLength,
                                  bool truncate = false) const;

    int64_t sot() const { return sot_; }
    int64_t eot() const { return eot_; }
    size_t vocab_size() const { return vocab_.size(); }
    const std::string& token(int64_t id) const;
    int64_t id(const std::string& token) const;  // an Error when absent

private:
    std::array<std::string, 256> byte_chars_;  // byte -> its printable stand-in, UTF-8
    std::vector<std::string> vocab_;
    std::unordered_map<std::string, int64_t> ids_;   // a repeated entry keeps its last id, as CLIP's dict does
    std::unordered_map<std::string, size_t> ranks_;  // "left right" -> merge rank (lower merges first)
    int64_t sot_ = 0, eot_ = 0;
};

}  // namespace t2imu
