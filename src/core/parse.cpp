#include "core/parse.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/error.hpp"

namespace t2imu {

std::optional<double> parse_number(const std::string& text) {
    if (text.empty()) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || end != text.c_str() + text.size()) return std::nullopt;
    return v;
}

std::optional<double> parse_finite(const std::string& text) {
    const std::optional<double> v = parse_number(text);
    if (!v || !std::isfinite(*v)) return std::nullopt;
    return v;
}

std::optional<long long> parse_integer(const std::string& text) {
    long long v = 0;
    const char* first = text.data();
    const char* last = first + text.size();
    const auto [end, error] = std::from_chars(first, last, v);
    if (text.empty() || error != std::errc() || end != last) return std::nullopt;
    return v;
}

double finite_number(const std::string& text, const std::string& source, const std::string& field,
                     const std::string& expected) {
    const std::optional<double> v = parse_finite(text);
    if (!v) throw Error(source, field, expected, "'" + text.substr(0, 40) + "'");
    return *v;
}

long long integer_in(const std::string& text, long long low, long long high, const std::string& source,
                     const std::string& field) {
    const std::optional<long long> v = parse_integer(text);
    if (!v || *v < low || *v > high)
        throw Error(source, field, "a whole number from " + std::to_string(low) + " to " + std::to_string(high),
                    "'" + text.substr(0, 40) + "'");
    return *v;
}

bool ends_with(const std::string& path, const std::string& suffix) {
    return path.size() >= suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
}

NamedOverrides parse_named_overrides(const std::string& text, const std::string& source) {
    NamedOverrides out;
    std::stringstream in(text);
    std::getline(in, out.name, ',');
    for (std::string item; std::getline(in, item, ',');) {
        const size_t eq = item.find('=');
        if (eq == std::string::npos) throw Error(source, item, "key=value");
        out.overrides.emplace_back(item.substr(0, eq), item.substr(eq + 1));
    }
    return out;
}

std::pair<int, int> parse_shard(const std::string& text, const std::string& source, const std::string& field) {
    const size_t slash = text.find('/');
    const std::optional<long long> i = slash == std::string::npos ? std::nullopt : parse_integer(text.substr(0, slash));
    const std::optional<long long> n =
        slash == std::string::npos ? std::nullopt : parse_integer(text.substr(slash + 1));
    if (!i || !n || *n < 1 || *n > 1000000 || *i < 1 || *i > *n)
        throw Error(source, field, "I/N with 1 <= I <= N", text);
    return {static_cast<int>(*i), static_cast<int>(*n)};
}

std::vector<std::string> split_list(const std::string& text, char separator) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, separator);)
        if (!item.empty()) out.push_back(item);
    return out;
}

}  // namespace t2imu
