// Strict reading of TOML configuration files (toml++): a key nobody reads is an error, so a typo in a config
// is refused with its name instead of silently leaving a default in place.
#pragma once
#include <toml++/toml.h>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "core/error.hpp"

namespace t2imu {

// The TOML document of `path`; throws Error with the parser's message.
toml::table parse_toml_file(const std::string& path);
toml::table parse_toml_text(const std::string& text, const std::string& source);  // errors name `source`

// One table of a config file; `name` is its dotted name in messages ("" for the top level).
class TomlSection {
public:
    TomlSection(const toml::table& table, std::string path, std::string name)
        : table_(table), path_(std::move(path)), name_(std::move(name)) {}

    // Leaves `value` unchanged when the key is absent; throws when it holds another type. An integer field takes
    // only a TOML integer: toml++ would convert a float such as 4.9e47 to an integer out of range (undefined
    // behaviour, found by fuzz/fuzz_sensor_toml). An unsigned field (a seed) takes only one from 0.
    template <class T>
    void read(const char* key, T& value) {
        if constexpr (std::is_unsigned_v<T> && !std::is_same_v<T, bool>) {
            if (!has(key)) return;  // the default is never read through int64 (one above INT64_MAX would be negative)
            int64_t v = 0;
            read(key, v);
            if (v < 0) throw Error(path_, field(key), "a whole number from 0", std::to_string(v));
            value = static_cast<T>(v);
            return;
        }
        read_keys_.insert(key);
        const toml::node* n = table_.get(key);
        if (!n) return;
        constexpr bool integer = std::is_integral_v<T> && !std::is_same_v<T, bool>;
        const auto v = integer && !n->is_integer() ? std::optional<T>() : n->value<T>();
        if (!v)
            throw Error(path_, field(key),
                        integer                       ? "an integer"
                        : std::is_same_v<T, bool>     ? "true or false"
                        : std::is_floating_point_v<T> ? "a number"
                                                      : "a string");
        value = *v;
    }
    void read(const char* key, std::vector<std::string>& values);  // an array of strings
    template <class T>
    void require(const char* key, T& value) {
        if (!table_.get(key)) throw Error(path_, field(key), "a value (required)");
        read(key, value);
    }
    bool has(const char* key) const { return table_.get(key) != nullptr; }
    // A sub-table (empty when absent) or an array of tables, read by the caller.
    TomlSection table(const char* key);
    std::vector<TomlSection> array_of_tables(const char* key);
    // Throws for the first key of this table that no read() named.
    void refuse_unknown_keys() const;

private:
    std::string field(const std::string& key) const { return name_.empty() ? key : name_ + "." + key; }
    const toml::table& table_;
    std::string path_, name_;
    std::set<std::string> read_keys_;
};

}  // namespace t2imu
