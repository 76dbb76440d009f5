#include "text/word_tokenizer.hpp"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>

namespace t2imu {

std::vector<std::string> split_words(const std::string& text) {
    std::vector<std::string> out;
    std::string current;
    const auto flush = [&] {
        if (!current.empty()) out.push_back(current), current.clear();
    };
    for (size_t i = 0; i < text.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const bool letter_before = !current.empty() && std::isalnum(static_cast<unsigned char>(current.back()));
        const bool letter_after = i + 1 < text.size() && std::isalnum(static_cast<unsigned char>(text[i + 1]));
        if (std::isspace(c)) {
            flush();
        } else if (c >= 0x80 || std::isalnum(c)) {
            current.push_back(static_cast<char>(std::tolower(c)));
        } else if ((c == '\'' || c == '-') && letter_before && letter_after) {
            current.push_back(static_cast<char>(c));
        } else {
            flush();
            out.push_back(std::string(1, static_cast<char>(c)));
        }
    }
    flush();
    return out;
}

namespace {

void lookup(const std::string& w, const WordVectors& v, std::vector<int>* out) {
    int i = v.index_of(w);
    if (i >= 0) return out->push_back(i);
    if (w.size() > 2 && w.compare(w.size() - 2, 2, "'s") == 0) return lookup(w.substr(0, w.size() - 2), v, out);
    if (w.find('-') != std::string::npos) {
        size_t start = 0;
        while (start <= w.size()) {
            const size_t dash = w.find('-', start);
            lookup(w.substr(start, dash == std::string::npos ? std::string::npos : dash - start), v, out);
            if (dash == std::string::npos) break;
            start = dash + 1;
        }
        return;
    }
    for (const char* suffix : {"s", "ed", "ing"}) {
        const std::string s(suffix);
        if (w.size() > s.size() + 2 && w.compare(w.size() - s.size(), s.size(), s) == 0 &&
            (i = v.index_of(w.substr(0, w.size() - s.size()))) >= 0)
            return out->push_back(i);
    }
    out->push_back(-1);
}

}  // namespace

std::vector<int> word_indices(const std::string& text, const WordVectors& vocabulary) {
    std::vector<int> out;
    for (const std::string& w : split_words(text)) lookup(w, vocabulary, &out);
    return out;
}

WordVectors vocabulary_used_in(const WordVectors& vectors, const std::vector<std::string>& paths) {
    namespace fs = std::filesystem;
    std::set<int> used;
    const auto read = [&](const fs::path& file) {
        std::ifstream in(file);
        std::string line;
        while (std::getline(in, line))
            for (int i : word_indices(line, vectors))
                if (i >= 0) used.insert(i);
    };
    for (const std::string& p : paths) {
        if (!fs::is_directory(p))
            read(p);
        else
            for (const auto& e : fs::recursive_directory_iterator(p))
                if (e.is_regular_file() && e.path().extension() == ".txt") read(e.path());
    }
    std::vector<std::string> words;
    std::vector<float> values;
    for (int i : used) {
        words.push_back(vectors.word(i));
        values.insert(values.end(), vectors.vector(i), vectors.vector(i) + WordVectors::kDims);
    }
    return WordVectors(std::move(words), std::move(values));
}

}  // namespace t2imu
