#include "text/caption_augment.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/error.hpp"
#include "motion/activity_names.hpp"
#include "text/word_tokenizer.hpp"

namespace t2imu {

namespace {

void unit_row(const float* v, float* out) {
    double norm = 0;
    for (int d = 0; d < WordVectors::kDims; ++d) norm += static_cast<double>(v[d]) * v[d];
    const float scale = norm > 0 ? static_cast<float>(1.0 / std::sqrt(norm)) : 0.0f;
    for (int d = 0; d < WordVectors::kDims; ++d) out[d] = v[d] * scale;
}

bool is_direction(const std::string& w) {
    static const char* const kDirections[] = {
        "up",        "down",  "upstairs",  "downstairs",       "upward",        "upwards",           "downward",
        "downwards", "left",  "right",     "forward",          "forwards",      "backward",          "backwards",
        "back",      "front", "clockwise", "counterclockwise", "anticlockwise", "counter-clockwise", "sideways"};
    return std::find(std::begin(kDirections), std::end(kDirections), w) != std::end(kDirections);
}

bool is_word(const std::string& token) {
    return std::any_of(token.begin(), token.end(), [](unsigned char c) { return std::isalpha(c); });
}

}  // namespace

void CaptionAugmentOptions::validate(const std::string& where) const {
    const auto probability = [&](const char* key, double v) {
        if (!(v >= 0 && v < 1))
            throw Error(where, std::string("augment.") + key, "a probability in [0, 1)", std::to_string(v));
    };
    probability("swap", swap);
    probability("dropout", dropout);
    if (neighbours < 1) throw Error(where, "augment.neighbours", "a whole number from 1", std::to_string(neighbours));
    if (!(min_similarity > 0 && min_similarity < 1))
        throw Error(where, "augment.min_similarity", "a cosine in (0, 1)", std::to_string(min_similarity));
    if (search_words < 1)
        throw Error(where, "augment.search_words", "a whole number from 1", std::to_string(search_words));
}

CaptionAugmenter::CaptionAugmenter(const WordVectors& vectors, const CaptionAugmentOptions& options,
                                   const std::vector<std::string>& captions)
    : vectors_(vectors), options_(options) {
    const int n = std::min(options.search_words, vectors.size());
    unit_.resize(static_cast<size_t>(n) * WordVectors::kDims);
    for (int w = 0; w < n; ++w) unit_row(vectors.vector(w), unit_.data() + static_cast<size_t>(w) * WordVectors::kDims);
    if (options.swap <= 0) return;
    for (const std::string& c : captions)
        for (const std::string& token : split_words(c)) {
            const int w = vectors.index_of(token);
            if (w >= 0) neighbours_of(w);
        }
}

const std::vector<int>& CaptionAugmenter::neighbours_of(int word) {
    auto found = neighbours_.find(word);
    if (found != neighbours_.end()) return found->second;
    float query[WordVectors::kDims];
    unit_row(vectors_.vector(word), query);
    std::vector<std::pair<float, int>> best;  // (similarity, word), at most `neighbours`, unordered
    const int n = static_cast<int>(unit_.size() / WordVectors::kDims);
    for (int w = 0; w < n; ++w) {
        if (w == word) continue;
        const float* u = unit_.data() + static_cast<size_t>(w) * WordVectors::kDims;
        float s = 0;
        for (int d = 0; d < WordVectors::kDims; ++d) s += query[d] * u[d];
        if (s < options_.min_similarity) continue;
        if (static_cast<int>(best.size()) < options_.neighbours) {
            best.emplace_back(s, w);
        } else {
            auto worst = std::min_element(best.begin(), best.end());
            if (s > worst->first) *worst = {s, w};
        }
    }
    std::sort(best.begin(), best.end(), [](const auto& a, const auto& b) {
        return a.first > b.first || (a.first == b.first && a.second < b.second);
    });
    std::vector<int>& out = neighbours_[word];
    for (const auto& b : best) out.push_back(b.second);
    return out;
}

std::string CaptionAugmenter::augment(const std::string& caption, std::mt19937_64& rng) {
    std::vector<std::string> tokens = split_words(caption);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<std::string> kept;
    for (size_t i = 0; i < tokens.size(); ++i) {
        const std::string& token = tokens[i];
        const double drop = u(rng), swap = u(rng);
        if (!is_word(token)) {
            kept.push_back(token);
            continue;
        }
        if (drop < options_.dropout) continue;
        const int w = vectors_.index_of(token);
        if (swap < options_.swap && w >= 0 && !is_direction(token)) {
            const std::vector<int>& near = neighbours_of(w);
            if (!near.empty()) {
                kept.push_back(vectors_.word(near[std::uniform_int_distribution<size_t>(0, near.size() - 1)(rng)]));
                continue;
            }
        }
        kept.push_back(token);
    }
    if (std::none_of(kept.begin(), kept.end(), is_word)) return caption;  // everything dropped: keep the caption
    std::string out;
    for (const std::string& t : kept) out += (out.empty() ? "" : " ") + t;
    return activity_named_in(out) == activity_named_in(caption) ? out : caption;
}

}  // namespace t2imu
