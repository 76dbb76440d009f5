// The one error type of t2imu. Its message names the file, the field and what was expected, so the CLI
// can print it as a single line: "FILE: FIELD: expected EXPECTED (got GOT)".
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>

namespace t2imu {

class Error : public std::runtime_error {
public:
    // file: the path (or a logical source such as "--joints"); field: the part of it that is wrong
    // (a header key, a column, "shape"); expected: what was expected, in words; got: what was found.
    Error(const std::string& file, const std::string& field, const std::string& expected, const std::string& got = "");
    explicit Error(const std::string& message);
};

// `text` safe to print on one line of a terminal: control bytes (newlines, escape sequences) as \xNN, bidi
// controls (U+200E/F, U+202A..E, U+2066..9, which reorder what follows) as \uNNNN, and cut after `max_bytes` with
// "... (N bytes)". Every Error's message goes through it: a 10 KB string or a 301-digit number from an input is
// quoted by its head, not echoed whole.
std::string printable_text(const std::string& text, size_t max_bytes);

}  // namespace t2imu
