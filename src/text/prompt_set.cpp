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
    if (bad != std::string::npos)
        throw Error(source, field, "UTF-8 text", "an invalid byte at offset " + std::to_string(bad));
    // C0 and C1 controls and DEL: a NUL or an escape sequence in a prompt is damage, not text.
    for (const char32_t c : decode_utf8(text)) {
        if (c < 0x20 || (c >= 0x7F && c <= 0x9F))
            throw Error(source, field, "text without control characters", code_point_name(c));
        // Bidi controls reorder how the text shows in a terminal, a report or a file name: what a reader sees would
        // not be what the model was asked.
        if (c == 0x061C || c == 0x200E || c == 0x200F || (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069))
            throw Error(source, field, "text without bidirectional control characters", code_point_name(c));
    }
}

std::vector<Prompt> parse_prompt_set(const std::string& text, const std::string& source, PromptActivity activity) {
    std::vector<Prompt> out;
    // A byte-order mark (editors on Windows write one) is no part of the first line's activity.
    std::istringstream in(text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? text.substr(3) : text);
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
        if (out.back().text.find_first_not_of(' ') == std::string::npos)
            throw Error(source, where, "a prompt after the tab (not blank)");
        if (activity == PromptActivity::required && out.back().activity.find_first_not_of(' ') == std::string::npos)
            throw Error(source, where, "an activity before the tab (not blank)");
    }
    if (out.empty()) throw Error(source, "prompts", "at least one prompt");
    return out;
}

std::vector<Prompt> read_prompt_set(const std::string& path, PromptActivity activity) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path, "file", "a readable prompts file");
    // Read up to a cap, never to the end: a file that never ends (/dev/zero, a pipe) would take all memory.
    std::string text(kMaxPromptFileBytes + 1, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<size_t>(in.gcount()));
    if (text.size() > kMaxPromptFileBytes) throw Error(path, "size", "a prompts file of at most 16 MiB");
    return parse_prompt_set(text, path, activity);
}

}  // namespace t2imu
