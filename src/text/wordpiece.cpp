#include "text/wordpiece.hpp"

#include <fstream>

#include "core/error.hpp"
#include "text/unicode_tables.hpp"
#include "text/utf8.hpp"

namespace t2imu {

namespace {

bool is_whitespace(char32_t c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == 0xA0 || (c >= 0x2000 && c <= 0x200A) || c == 0x3000;
}
bool is_control(char32_t c) { return (c < 0x20 && c != '\t' && c != '\n' && c != '\r') || (c >= 0x7F && c < 0xA0); }
bool is_cjk(char32_t c) {
    return (c >= 0x4E00 && c <= 0x9FFF) || (c >= 0x3400 && c <= 0x4DBF) || (c >= 0x20000 && c <= 0x2A6DF) ||
           (c >= 0xF900 && c <= 0xFAFF);
}
bool is_punctuation(char32_t c) {
    if ((c >= 33 && c <= 47) || (c >= 58 && c <= 64) || (c >= 91 && c <= 96) || (c >= 123 && c <= 126)) return true;
    switch (c) {
        case 0xA1:
        case 0xA7:
        case 0xAB:
        case 0xB6:
        case 0xB7:
        case 0xBB:
        case 0xBF: return true;
        default: break;
    }
    return (c >= 0x2010 && c <= 0x2027) || (c >= 0x2030 && c <= 0x205E) || (c >= 0x3001 && c <= 0x3003) ||
           (c >= 0x3008 && c <= 0x3011) || (c >= 0x3014 && c <= 0x301F) ||
           (c >= 0xFF01 && c <= 0xFF0F && c != 0xFF04 && c != 0xFF0B) ||
           (c >= 0xFF1A && c <= 0xFF20 && c != 0xFF1C && c != 0xFF1D && c != 0xFF1E);
}

// Lower case, then the base letter of an accented letter (unicode_tables.hpp).
char32_t lower_unaccented(char32_t c) {
    using namespace unicode_tables;
    if (c >= 'A' && c <= 'Z') return c + 32;
    if (c >= kLatinFirst && c <= kLatinLast) return kLatinLowerBase[c - kLatinFirst];
    if (c >= kGreekFirst && c <= kGreekLast) return kGreekLowerBase[c - kGreekFirst];
    return c;
}

}  // namespace

WordPieceTokenizer::WordPieceTokenizer(std::vector<std::string> vocab) : vocab_(std::move(vocab)) {
    for (size_t i = 0; i < vocab_.size(); ++i) ids_.emplace(vocab_[i], static_cast<int64_t>(i));
    for (const char* special : {"[UNK]", "[CLS]", "[SEP]"})
        if (!ids_.count(special)) throw Error("vocab", special, "the BERT special tokens");
}

WordPieceTokenizer WordPieceTokenizer::from_vocab_file(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path, "file", "a readable vocab.txt");
    std::vector<std::string> vocab;
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        vocab.push_back(line);
    }
    return WordPieceTokenizer(std::move(vocab));
}

int64_t WordPieceTokenizer::id(const std::string& token) const {
    const auto it = ids_.find(token);
    return it == ids_.end() ? ids_.at("[UNK]") : it->second;
}

std::vector<std::string> WordPieceTokenizer::basic_tokens(const std::string& text) const {
    std::vector<std::string> out;
    std::u32string word;
    const auto flush = [&] {
        if (!word.empty()) out.push_back(encode_utf8(word)), word.clear();
    };
    for (char32_t c : decode_utf8(text)) {
        if (c == 0 || c == 0xFFFD || is_control(c)) continue;
        if (c >= 0x300 && c <= 0x36F) continue;  // combining marks: accents already decomposed
        if (is_whitespace(c)) {
            flush();
        } else if (is_cjk(c) || is_punctuation(c)) {
            flush();
            out.push_back(encode_utf8(std::u32string(1, c)));
        } else {
            word.push_back(lower_unaccented(c));
        }
    }
    flush();
    return out;
}

std::vector<std::string> WordPieceTokenizer::wordpieces(const std::string& text) const {
    std::vector<std::string> out;
    for (const std::string& word : basic_tokens(text)) {
        if (decode_utf8(word).size() > 100) {
            out.push_back("[UNK]");
            continue;
        }
        std::vector<std::string> pieces;
        size_t start = 0;
        bool bad = false;
        while (start < word.size()) {
            size_t end = word.size();
            std::string found;
            while (end > start) {
                // Only cut at UTF-8 character boundaries.
                if (end < word.size() && (static_cast<unsigned char>(word[end]) >> 6) == 2) {
                    --end;
                    continue;
                }
                const std::string piece = (start > 0 ? "##" : "") + word.substr(start, end - start);
                if (ids_.count(piece)) {
                    found = piece;
                    break;
                }
                --end;
            }
            if (found.empty()) {
                bad = true;
                break;
            }
            pieces.push_back(found);
            start = end;
        }
        if (bad)
            out.push_back("[UNK]");
        else
            out.insert(out.end(), pieces.begin(), pieces.end());
    }
    return out;
}

std::vector<int64_t> WordPieceTokenizer::encode(const std::string& text, size_t max_length) const {
    std::vector<int64_t> ids = {id("[CLS]")};
    for (const std::string& p : wordpieces(text)) {
        if (ids.size() + 1 >= max_length) break;
        ids.push_back(id(p));
    }
    ids.push_back(id("[SEP]"));
    return ids;
}

}  // namespace t2imu
