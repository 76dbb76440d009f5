#include "core/number_text.hpp"

#include <algorithm>
#include <charconv>
#include <string_view>

#include "core/error.hpp"

namespace t2imu {

namespace {

// DBL_MAX in fixed notation is 309 digits; with a sign, a point and 17 decimals 328 characters.
constexpr int kMaxDecimals = 17;
constexpr size_t kBufferSize = 400;

std::string_view to_text(char (&buf)[kBufferSize], double v, std::chars_format format, int precision) {
    const std::to_chars_result r = std::to_chars(buf, buf + kBufferSize, v, format, precision);
    if (r.ec != std::errc())
        throw Error("number_text", "buffer", std::to_string(kBufferSize) + " characters for any double");
    return std::string_view(buf, static_cast<size_t>(r.ptr - buf));
}

}  // namespace

void append_fixed(std::string& out, double v, int decimals) {
    char buf[kBufferSize];
    std::string_view s = to_text(buf, v, std::chars_format::fixed, std::clamp(decimals, 0, kMaxDecimals));
    if (s.find('.') != std::string_view::npos) {
        while (s.back() == '0') s.remove_suffix(1);
        if (s.back() == '.') s.remove_suffix(1);
    }
    if (s == "-0") s = "0";
    out.append(s);
}

std::string fixed_text(double v, int decimals) {
    std::string out;
    append_fixed(out, v, decimals);
    return out;
}

std::string general_text(double v, int significant) {
    char buf[kBufferSize];
    return std::string(to_text(buf, v, std::chars_format::general, std::clamp(significant, 1, kMaxDecimals)));
}

}  // namespace t2imu
