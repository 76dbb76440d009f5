// The headings of a Markdown file and their anchors as GitHub makes them, for the tests that check pointers into
// README.md and docs/ (tests/test_docs_links.cpp, tests/test_source_comments.cpp).
#pragma once
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace t2imu::test {

inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// GitHub's anchor of a heading: lower case, spaces to '-', punctuation dropped (letters beyond ASCII kept).
inline std::string heading_anchor(const std::string& heading) {
    std::string out;
    for (size_t i = 0; i < heading.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(heading[i]);
        if (c >= 0x80) {
            // "±" (C2 B1), "–" and "—" (E2 80 93/94) are punctuation to GitHub; other UTF-8 is kept as letters.
            if (c == 0xC2 && i + 1 < heading.size() && static_cast<unsigned char>(heading[i + 1]) == 0xB1) {
                ++i;
                continue;
            }
            if (c == 0xE2 && i + 2 < heading.size()) {
                i += 2;
                continue;
            }
            out += heading[i];
        } else if (std::isalnum(c) || c == '-' || c == '_') {
            out += static_cast<char>(std::tolower(c));
        } else if (c == ' ') {
            out += '-';
        }
    }
    return out;
}

struct Headings {
    std::set<std::string> texts;    // as written, without the leading #s
    std::set<std::string> anchors;  // repeated headings get -1, -2, ... as on GitHub
};

// The ATX headings ("## Title") of a Markdown file, outside fenced code blocks.
inline Headings markdown_headings(const std::filesystem::path& path) {
    Headings h;
    std::map<std::string, int> seen;
    std::istringstream in(read_text(path));
    bool fenced = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("```", 0) == 0) fenced = !fenced;
        if (fenced || line.empty() || line[0] != '#') continue;
        const size_t text = line.find_first_not_of('#');
        if (text == std::string::npos || line[text] != ' ') continue;
        std::string title = line.substr(text + 1);
        while (!title.empty() && (title.back() == ' ' || title.back() == '\r')) title.pop_back();
        h.texts.insert(title);
        const std::string anchor = heading_anchor(title);
        const int n = seen[anchor]++;
        h.anchors.insert(n == 0 ? anchor : anchor + "-" + std::to_string(n));
    }
    return h;
}

}  // namespace t2imu::test
