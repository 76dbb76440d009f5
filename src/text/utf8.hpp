// UTF-8 <-> code points, shared by the tokenizers.
#pragma once
#include <string>
#include <vector>

namespace t2imu {

// An invalid or truncated byte sequence becomes U+FFFD (one per offending lead byte).
std::vector<char32_t> decode_utf8(const std::string& s);
std::string encode_utf8(const std::u32string& s);
void append_utf8(std::string& out, char32_t c);
// The byte offset of the first byte that is not well-formed UTF-8 (RFC 3629: no overlong forms, no surrogates,
// nothing above U+10FFFF), or std::string::npos when `s` is valid.
size_t first_invalid_utf8(const std::string& s);

}  // namespace t2imu
