#include "text/prompt_set.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "text/utf8.hpp"

namespace t2imu {

namespace {

std::string code_point_name(char32_t c) {
    char name[16];
    std::snprintf(name, sizeof name, "U+%04X", static_cast<unsigned>(c));
    return name;
}

}  // namespace

void check_prompt_text(const std::string& text, const std::string& source, const std::string& field) {
    const size_t bad = first_invalid_utf8(text);
    if (bad != std::string::npos) throw Error(source, field, "UTF-8 text", "an invalid byte at offset " + std::to_string(bad));
    // C0 and C1 controls and DEL: a NUL or an escape sequence in a prompt is damage, not text.
    for (const char32_t c : decode_utf8(text))
        if (c < 0x20 || (c >= 0x7F && c <= 0x9F)) throw Error(source, field, "text without control characters", code_point_name(c));
}

std::vector<Prompt> parse_prompt_set(const std::string& text, const std::string& source, PromptActivity activity) {
    std::vector<Prompt> out;
    std::istringstream in(text);
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        const std::string where = "line " + std::to_string(++number);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        const size_t tab = line.find('\t');
        if (tab == std::string::npos) {
            if (activity == PromptActivity::required) throw Error(source, where, "activity<TAB>prompt (no TAB found)");
            out.push_back({"", line});
        } else {
            out.push_back({line.substr(0, tab), line.substr(tab + 1)});
        }
        check_prompt_text(out.back().activity, source, where);
        check_prompt_text(out.back().text, source, where);
        if (out.back().text.empty()) throw Error(source, where, "a prompt after the tab");
        if (activity == PromptActivity::required && out.back().activity.empty()) throw Error(source, where, "an activity before the tab");
    }
    if (out.empty()) throw Error(source, "prompts", "at least one prompt");
    return out;
}

std::vector<Prompt> read_prompt_set(const std::string& path, PromptActivity activity) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path, "file", "a readable prompts file");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_prompt_set(text.str(), path, activity);
}

}  // namespace t2imu
