// UTF-8 <-> code points, shared by the tokenizers.
#pragma once
#include <string>
#include <vector>

namespace t2imu {

// An invalid or truncated byte sequence becomes U+FFFD (one per offending lead byte).
std::vector<char32_t> decode_utf8(const std::string& s);
std::string encode_utf8(const std::u32string& s);
void append_utf8(std::string& out, char32_t c);

}  // namespace t2imu
