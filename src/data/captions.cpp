#include "data/captions.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"

namespace t2imu {

CaptionLine parse_caption_line(const std::string& line, const std::string& source) {
    // The caption itself may not contain '#'; split on the last three.
    std::vector<size_t> hashes;
    for (size_t i = line.size(); i-- > 0 && hashes.size() < 3;)
        if (line[i] == '#') hashes.push_back(i);
    if (hashes.size() < 3) throw Error(source, "caption line", "caption#tokens#start#end", line);
    CaptionLine c;
    c.caption = line.substr(0, hashes[2]);
    c.tokens = line.substr(hashes[2] + 1, hashes[1] - hashes[2] - 1);
    auto tag = [&](size_t from, size_t to) {
        const std::string s = line.substr(from, to - from);
        const std::optional<double> v = parse_finite(s);
        if (!v || *v < 0) throw Error(source, "caption time", "seconds >= 0 (or nan, read as 0)", s);
        return *v;
    };
    // HumanML3D writes 'nan' for missing tags; the official loader reads them as 0 (whole clip).
    const std::string start = line.substr(hashes[1] + 1, hashes[0] - hashes[1] - 1), end = line.substr(hashes[0] + 1);
    c.start_s = start == "nan" ? 0.0 : tag(hashes[1] + 1, hashes[0]);
    c.end_s = end == "nan" ? 0.0 : tag(hashes[0] + 1, line.size());
    if (!c.whole_clip() && c.end_s <= c.start_s) throw Error(source, "caption time", "end after start", line);
    return c;
}

std::vector<CaptionLine> read_caption_file(const std::string& path) {
    std::istringstream in(read_file_text(path));
    std::vector<CaptionLine> out;
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (!line.empty()) out.push_back(parse_caption_line(line, path));
    }
    return out;
}

std::string format_caption_line(const CaptionLine& c) {
    char tags[64];
    std::snprintf(tags, sizeof tags, "#%.1f#%.1f", c.start_s, c.end_s);
    return c.caption + "#" + c.tokens + tags;
}

static std::string with_case_of(const std::string& word, const std::string& model) {
    std::string out = word;
    const bool all_upper = model.size() > 1 && std::isupper(static_cast<unsigned char>(model[1]));
    for (size_t i = 0; i < out.size(); ++i) {
        const bool upper = i == 0 ? std::isupper(static_cast<unsigned char>(model[0])) : all_upper;
        out[i] = static_cast<char>(upper ? std::toupper(static_cast<unsigned char>(out[i]))
                                         : std::tolower(static_cast<unsigned char>(out[i])));
    }
    return out;
}

std::string swap_left_right(const std::string& caption) {
    std::string out;
    size_t i = 0;
    while (i < caption.size()) {
        if (!std::isalpha(static_cast<unsigned char>(caption[i]))) {
            out += caption[i++];
            continue;
        }
        size_t j = i;
        while (j < caption.size() && std::isalpha(static_cast<unsigned char>(caption[j]))) ++j;
        const std::string word = caption.substr(i, j - i);
        std::string lower = word;
        for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (lower == "left")
            out += with_case_of("right", word);
        else if (lower == "right")
            out += with_case_of("left", word);
        else
            out += word;
        i = j;
    }
    return out;
}

std::vector<std::string> read_caption_corpus(const std::string& path) {
    std::vector<std::string> files;
    if (std::filesystem::is_directory(path)) {
        for (const auto& e : std::filesystem::directory_iterator(path))
            if (e.path().extension() == ".txt") files.push_back(e.path().string());
    } else {
        files.push_back(path);
    }
    std::sort(files.begin(), files.end());
    std::vector<std::string> captions;
    for (const std::string& f : files)
        for (const CaptionLine& c : read_caption_file(f)) captions.push_back(c.caption);
    if (captions.empty()) throw Error(path, "captions", "at least one caption");
    return captions;
}

}  // namespace t2imu
