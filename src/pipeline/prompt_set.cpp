#include "pipeline/prompt_set.hpp"

#include <fstream>

#include "core/error.hpp"

namespace t2imu {

std::vector<Prompt> read_prompt_set(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path, "file", "a readable prompts file");
    std::vector<Prompt> out;
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        const size_t tab = line.find('\t');
        if (tab == std::string::npos) out.push_back({"", line});
        else out.push_back({line.substr(0, tab), line.substr(tab + 1)});
        if (out.back().text.empty()) throw Error(path, "line " + std::to_string(out.size()), "a prompt after the tab");
    }
    if (out.empty()) throw Error(path, "prompts", "at least one prompt");
    return out;
}

}  // namespace t2imu
