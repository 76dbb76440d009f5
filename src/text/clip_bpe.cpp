#include "text/clip_bpe.hpp"

#include <zlib.h>

#include <limits>
#include <sstream>

#include "core/error.hpp"
#include "text/unicode_classes.hpp"
#include "text/utf8.hpp"

namespace t2imu {

namespace {

const char* const kSot = "<|startoftext|>";
const char* const kEot = "<|endoftext|>";
const char* const kEndOfWord = "</w>";

// Python's str.isspace (the set its re module's \s matches in CLIP's whitespace_clean).
bool is_space(char32_t c) {
    return (c >= 0x09 && c <= 0x0D) || (c >= 0x1C && c <= 0x20) || c == 0x85 || c == 0xA0 || c == 0x1680 ||
           (c >= 0x2000 && c <= 0x200A) || c == 0x2028 || c == 0x2029 || c == 0x202F || c == 0x205F || c == 0x3000;
}

// The byte table's order: the printable bytes ascending, then the others ascending (stand-ins U+0100 on).
std::vector<int> byte_order() {
    std::vector<int> printable, rest;
    for (int b = 0; b < 256; ++b)
        ((b >= 33 && b <= 126) || (b >= 161 && b <= 172) || (b >= 174 && b <= 255) ? printable : rest).push_back(b);
    printable.insert(printable.end(), rest.begin(), rest.end());
    return printable;
}

bool starts_with(const std::vector<char32_t>& s, size_t at, const char* literal) {
    for (size_t k = 0; literal[k] != '\0'; ++k)
        if (at + k >= s.size() || s[at + k] != static_cast<char32_t>(static_cast<unsigned char>(literal[k])))
            return false;
    return true;
}

// Python's str.lower() writes capital sigma at the end of a word as final sigma (Unicode's Final_Sigma
// context, with "cased" approximated by "letter" and no case-ignorable marks skipped).
bool ends_word(const std::vector<char32_t>& s, size_t i) {
    return i > 0 && unicode_classes::is_letter(s[i - 1]) &&
           (i + 1 == s.size() || !unicode_classes::is_letter(s[i + 1]));
}

std::string read_maybe_gzip(const std::string& path) {
    // zlib reads a plain file through unchanged, so one path serves both.
    gzFile f = gzopen(path.c_str(), "rb");
    if (f == nullptr)
        throw Error(path, "file", "a readable CLIP merges file (bpe_simple_vocab_16e6.txt.gz or its plain text)");
    std::string out;
    char buffer[1 << 16];
    int n = 0;
    while ((n = gzread(f, buffer, sizeof buffer)) > 0) out.append(buffer, static_cast<size_t>(n));
    int code = Z_OK;
    const std::string message = n < 0 ? gzerror(f, &code) : "";
    gzclose(f);
    if (n < 0) throw Error(path, "gzip", "a complete gzip stream", message);
    return out;
}

}  // namespace

ClipBpeTokenizer::ClipBpeTokenizer(const std::vector<std::pair<std::string, std::string>>& merges) {
    const std::vector<int> order = byte_order();
    for (size_t k = 0; k < order.size(); ++k) {
        const int b = order[k];
        const char32_t stand_in = k < 188 ? static_cast<char32_t>(b) : static_cast<char32_t>(256 + (k - 188));
        byte_chars_[static_cast<size_t>(b)] = encode_utf8(std::u32string(1, stand_in));
    }
    for (int b : order) vocab_.push_back(byte_chars_[static_cast<size_t>(b)]);
    for (int b : order) vocab_.push_back(byte_chars_[static_cast<size_t>(b)] + kEndOfWord);
    for (size_t r = 0; r < merges.size(); ++r) {
        vocab_.push_back(merges[r].first + merges[r].second);
        ranks_[merges[r].first + " " + merges[r].second] =
            r;  // a repeated merge keeps its last rank, as in CLIP's dict
    }
    vocab_.push_back(kSot);
    vocab_.push_back(kEot);
    for (size_t i = 0; i < vocab_.size(); ++i) ids_[vocab_[i]] = static_cast<int64_t>(i);
    sot_ = ids_.at(kSot);
    eot_ = ids_.at(kEot);
}

ClipBpeTokenizer ClipBpeTokenizer::from_merges_file(const std::string& path, size_t max_merges) {
    std::istringstream in(read_maybe_gzip(path));
    std::string line;
    std::getline(in, line);  // "#version: 0.2"
    std::vector<std::pair<std::string, std::string>> merges;
    size_t line_no = 1, blank_at = 0;
    while (merges.size() < max_merges && std::getline(in, line)) {
        ++line_no;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) {
            blank_at = blank_at ? blank_at : line_no;
            continue;
        }
        // A blank line inside the merges would shift every later id against CLIP's.
        if (blank_at) throw Error(path, "line " + std::to_string(blank_at), "a merge \"left right\"", "an empty line");
        std::istringstream fields(line);
        std::string left, right, extra;
        if (!(fields >> left >> right) || (fields >> extra))
            throw Error(path, "line " + std::to_string(line_no), "a merge \"left right\"", line);
        merges.emplace_back(left, right);
    }
    if (merges.empty()) throw Error(path, "merges", "at least one merge after the header line", "none");
    return ClipBpeTokenizer(merges);
}

std::string ClipBpeTokenizer::clean(const std::string& text) {
    const std::vector<char32_t> s = decode_utf8(text);
    std::string out;
    bool pending_space = false;
    for (size_t i = 0; i < s.size(); ++i) {
        char32_t c = s[i];
        if (is_space(c)) {
            pending_space = !out.empty();
            continue;
        }
        if (pending_space) out.push_back(' ');
        pending_space = false;
        if (c == 0x02BC || (c >= 0x2018 && c <= 0x201B))
            c = '\'';
        else if (c >= 0x201C && c <= 0x201F)
            c = '"';
        if (c == 0x0130) {
            append_utf8(out, 'i');  // the one code point whose lower case is two: i + combining dot above
            append_utf8(out, 0x0307);
        } else if (c == 0x03A3 && ends_word(s, i)) {
            append_utf8(out, 0x03C2);  // final sigma
        } else {
            append_utf8(out, unicode_classes::to_lower(c));
        }
    }
    return out;
}

std::vector<std::string> ClipBpeTokenizer::split(const std::string& cleaned) {
    using unicode_classes::is_letter;
    using unicode_classes::is_number;
    const std::vector<char32_t> s = decode_utf8(cleaned);
    std::vector<std::string> out;
    size_t i = 0;
    const auto take = [&](size_t end) {
        out.push_back(encode_utf8(
            std::u32string(s.begin() + static_cast<std::ptrdiff_t>(i), s.begin() + static_cast<std::ptrdiff_t>(end))));
        i = end;
    };
    while (i < s.size()) {
        const char32_t c = s[i];
        if (is_space(c)) {
            ++i;
            continue;
        }
        bool matched = false;
        for (const char* literal : {kSot, kEot, "'s", "'t", "'re", "'ve", "'m", "'ll", "'d"})
            if (starts_with(s, i, literal)) {
                take(i + std::char_traits<char>::length(literal));
                matched = true;
                break;
            }
        if (matched) continue;
        size_t end = i + 1;
        if (is_letter(c)) {
            while (end < s.size() && is_letter(s[end])) ++end;
        } else if (!is_number(c)) {
            while (end < s.size() && !is_space(s[end]) && !is_letter(s[end]) && !is_number(s[end])) ++end;
        }
        take(end);
    }
    return out;
}

std::vector<std::string> ClipBpeTokenizer::bpe(const std::string& piece) const {
    if (piece == kSot || piece == kEot) return {piece};
    std::vector<std::string> word;
    for (unsigned char b : piece) word.push_back(byte_chars_[b]);
    if (word.empty()) return {};
    word.back() += kEndOfWord;
    while (word.size() > 1) {
        size_t best = std::numeric_limits<size_t>::max();
        std::string first, second;
        for (size_t k = 0; k + 1 < word.size(); ++k) {
            const auto it = ranks_.find(word[k] + " " + word[k + 1]);
            if (it != ranks_.end() && it->second < best) {
                best = it->second;
                first = word[k];
                second = word[k + 1];
            }
        }
        if (best == std::numeric_limits<size_t>::max()) break;
        // Every non-overlapping occurrence of the pair, left to right.
        std::vector<std::string> merged;
        for (size_t k = 0; k < word.size();) {
            if (k + 1 < word.size() && word[k] == first && word[k + 1] == second) {
                merged.push_back(first + second);
                k += 2;
            } else {
                merged.push_back(word[k]);
                ++k;
            }
        }
        word = std::move(merged);
    }
    return word;
}

std::vector<int64_t> ClipBpeTokenizer::encode(const std::string& text) const {
    std::vector<int64_t> ids;
    for (const std::string& piece : split(clean(text)))
        for (const std::string& entry : bpe(piece)) ids.push_back(id(entry));
    return ids;
}

std::vector<int64_t> ClipBpeTokenizer::tokenize(const std::string& text, int64_t context_length, bool truncate) const {
    if (context_length < 2)
        throw Error("clip tokenizer", "context_length", "at least 2 (SOT and EOT)", std::to_string(context_length));
    std::vector<int64_t> ids = {sot_};
    for (int64_t t : encode(text)) ids.push_back(t);
    ids.push_back(eot_);
    const size_t n = static_cast<size_t>(context_length);
    if (ids.size() > n) {
        if (!truncate)
            throw Error("clip tokenizer", "\"" + text + "\"",
                        "at most " + std::to_string(n) + " tokens with SOT and EOT", std::to_string(ids.size()));
        ids.resize(n);
        ids.back() = eot_;
    }
    ids.resize(n, 0);
    return ids;
}

const std::string& ClipBpeTokenizer::token(int64_t id) const {
    if (id < 0 || static_cast<size_t>(id) >= vocab_.size())
        throw Error("clip tokenizer", "id", "0 to " + std::to_string(vocab_.size() - 1), std::to_string(id));
    return vocab_[static_cast<size_t>(id)];
}

int64_t ClipBpeTokenizer::id(const std::string& token) const {
    const auto it = ids_.find(token);
    if (it == ids_.end()) throw Error("clip tokenizer", "token", "an entry of the BPE vocabulary", token);
    return it->second;
}

}  // namespace t2imu
