// BERT's tokenizer (uncased; as all-MiniLM-L6-v2 uses it): a basic tokenizer, then greedy longest-match-first
// WordPiece over `vocab.txt`, wrapped in [CLS] ... [SEP] and truncated to a maximum length.
//
// Basic tokenizer, as Hugging Face's BertTokenizer with do_lower_case: drop control characters and U+FFFD,
// turn whitespace into spaces, put spaces around CJK ideographs, lower-case, strip accents (decompose and drop
// combining marks), split off punctuation (ASCII symbols 33-47, 58-64, 91-96, 123-126 and Unicode category P).
// Unicode coverage: lower-casing and accent stripping for Latin-1 Supplement, Latin Extended-A/B and Greek; the
// category-P test for the Latin-1, General Punctuation, CJK Symbols and Fullwidth blocks. Text outside these
// blocks passes through unchanged (as whole characters).
#pragma once
#include <string>
#include <unordered_map>
#include <vector>

namespace t2imu {

class WordPieceTokenizer {
public:
    static WordPieceTokenizer from_vocab_file(const std::string& path);  // one token per line, id = line number
    explicit WordPieceTokenizer(std::vector<std::string> vocab);

    std::vector<std::string> basic_tokens(const std::string& text) const;
    std::vector<std::string> wordpieces(const std::string& text) const;  // without [CLS]/[SEP]
    // [CLS] ids [SEP], at most max_length ids (the word pieces are truncated).
    std::vector<int64_t> encode(const std::string& text, size_t max_length = 256) const;
    int64_t id(const std::string& token) const;  // the [UNK] id when absent

private:
    std::vector<std::string> vocab_;
    std::unordered_map<std::string, int64_t> ids_;
};

}  // namespace t2imu
