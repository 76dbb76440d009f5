#include "core/toml_section.hpp"

namespace t2imu {

namespace {
const toml::table kEmptyTable;
}

toml::table parse_toml_text(const std::string& text, const std::string& source) {
    try {
        return toml::parse(text, source);
    } catch (const toml::parse_error& e) {
        throw Error(source, "toml", "a valid TOML file", std::string(e.description()));
    }
}

toml::table parse_toml_file(const std::string& path) {
    try {
        return toml::parse_file(path);
    } catch (const toml::parse_error& e) {
        throw Error(path, "toml", "a valid TOML file", std::string(e.description()));
    }
}

void TomlSection::read(const char* key, std::vector<std::string>& values) {
    read_keys_.insert(key);
    const toml::node* n = table_.get(key);
    if (!n) return;
    const toml::array* a = n->as_array();
    if (!a) throw Error(path_, field(key), "an array of strings");
    values.clear();
    for (const toml::node& item : *a) {
        const auto s = item.value<std::string>();
        if (!s) throw Error(path_, field(key), "an array of strings");
        values.push_back(*s);
    }
}

TomlSection TomlSection::table(const char* key) {
    read_keys_.insert(key);
    const toml::node* n = table_.get(key);
    if (!n) return TomlSection(kEmptyTable, path_, field(key));
    if (!n->as_table()) throw Error(path_, field(key), "a table ([" + field(key) + "])");
    return TomlSection(*n->as_table(), path_, field(key));
}

std::vector<TomlSection> TomlSection::array_of_tables(const char* key) {
    read_keys_.insert(key);
    std::vector<TomlSection> out;
    const toml::node* n = table_.get(key);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a) throw Error(path_, field(key), "an array of tables ([[" + field(key) + "]])");
    for (size_t i = 0; i < a->size(); ++i) {
        const toml::table* t = a->get(i)->as_table();
        if (!t) throw Error(path_, field(key), "an array of tables ([[" + field(key) + "]])");
        out.emplace_back(*t, path_, field(key) + "[" + std::to_string(i) + "]");
    }
    return out;
}

void TomlSection::refuse_unknown_keys() const {
    for (const auto& [k, v] : table_)
        if (!read_keys_.count(std::string(k.str()))) throw Error(path_, field(std::string(k.str())), "a known key");
}

}  // namespace t2imu
