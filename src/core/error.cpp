#include "core/error.hpp"

#include <cctype>
#include <cstdio>

namespace t2imu {

namespace {

// What an Error quotes from its input (`got`: room for a path and a nested error) and what it may say in all; a run
// of more digits than any meaningful number has is quoted by its head.
constexpr size_t kMaxGot = 400, kMaxMessage = 2000, kMaxDigits = 24, kDigitsKept = 12;

// The length of the bidi control starting at text[i] (3 UTF-8 bytes), or 0.
size_t bidi_control_at(const std::string& text, size_t i) {
    if (i + 2 >= text.size() || static_cast<unsigned char>(text[i]) != 0xE2) return 0;
    const unsigned char b1 = static_cast<unsigned char>(text[i + 1]), b2 = static_cast<unsigned char>(text[i + 2]);
    const bool marks = b1 == 0x80 && (b2 == 0x8E || b2 == 0x8F || (b2 >= 0xAA && b2 <= 0xAE));  // LRM, RLM, LRE..RLO
    const bool isolates = b1 == 0x81 && b2 >= 0xA6 && b2 <= 0xA9;                               // LRI..PDI
    return marks || isolates ? 3 : 0;
}

std::string compose(const std::string& file, const std::string& field, const std::string& expected,
                    const std::string& got) {
    std::string m = file.empty() ? std::string() : file + ": ";
    if (!field.empty()) m += field + ": ";
    m += "expected " + expected;
    if (!got.empty()) m += " (got " + printable_text(got, kMaxGot) + ")";
    return m;
}

}  // namespace

std::string printable_text(const std::string& text, size_t max_bytes) {
    std::string out;
    size_t i = 0;
    for (; i < text.size() && out.size() < max_bytes; ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        char code[16];
        if (const size_t n = bidi_control_at(text, i)) {
            const unsigned cp = ((static_cast<unsigned char>(text[i + 1]) & 0x3Fu) << 6 |
                                 (static_cast<unsigned char>(text[i + 2]) & 0x3Fu)) |
                                0x2000u;
            std::snprintf(code, sizeof code, "\\u%04X", cp);
            out += code;
            i += n - 1;
        } else if (std::isdigit(c) && (i == 0 || !std::isdigit(static_cast<unsigned char>(text[i - 1])))) {
            size_t end = i;
            while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
            const size_t digits = end - i;
            out += digits > kMaxDigits ? text.substr(i, kDigitsKept) + "...(" + std::to_string(digits) + " digits)"
                                       : text.substr(i, digits);
            i = end - 1;
        } else if (c < 0x20 || c == 0x7F) {
            std::snprintf(code, sizeof code, "\\x%02X", c);
            out += code;
        } else {
            out += static_cast<char>(c);
        }
    }
    while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80)
        out += text[i++];  // finish a UTF-8 character
    if (i < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

Error::Error(const std::string& message) : std::runtime_error(printable_text(message, kMaxMessage)) {}

Error::Error(const std::string& file, const std::string& field, const std::string& expected, const std::string& got)
    : std::runtime_error(printable_text(compose(file, field, expected, got), kMaxMessage)) {}

}  // namespace t2imu
