// Strict conversions of text to numbers and lists, in one place. "Strict": the whole text must be the number,
// as strtod (real numbers: decimal, exponent, "nan", "inf"; leading blanks allowed, as strtod allows them) or
// from_chars (integers: decimal digits with an optional '-', no blanks, no '+') reads it; "1.5x", "", "1 2" and
// an integer beyond long long's range are not numbers. The std::optional forms leave the message to the caller
// (who knows the line and column); the throwing forms name `source` and `field` in the project's one-line Error.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace t2imu {

std::optional<double> parse_number(const std::string& text);  // nan and inf included
std::optional<double> parse_finite(const std::string& text);  // nan and inf refused
std::optional<long long> parse_integer(const std::string& text);

// A finite number; Error(source, field, expected, text) otherwise.
double finite_number(const std::string& text, const std::string& source, const std::string& field,
                     const std::string& expected = "a number");
// An integer from `low` to `high`; Error(source, field, "a whole number from low to high", text) otherwise.
long long integer_in(const std::string& text, long long low, long long high, const std::string& source,
                     const std::string& field);

// Whether `path` ends with `suffix` (".toml", "_joints.npy"): how options tell a file from a preset name.
bool ends_with(const std::string& path, const std::string& suffix);

// "NAME,key=value,key=value" (a preset and its overrides: a sensor model, --body population:N,...): the name and the
// key=value items in order, their values left as text for the caller's own parser. Error(source, item, "key=value")
// for an item without '=' (an empty one included; a trailing comma is ignored).
struct NamedOverrides {
    std::string name;
    std::vector<std::pair<std::string, std::string>> overrides;  // key, value
};
NamedOverrides parse_named_overrides(const std::string& text, const std::string& source);

// "I/N" with 1 <= I <= N (a shard of N); Error(source, field, "I/N with 1 <= I <= N", text) otherwise.
std::pair<int, int> parse_shard(const std::string& text, const std::string& source, const std::string& field);

// "a,b,,c" -> {"a", "b", "c"}: the items between `separator`s, empty ones dropped (so "" gives none).
std::vector<std::string> split_list(const std::string& text, char separator = ',');

}  // namespace t2imu
