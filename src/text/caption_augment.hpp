// Caption augmentation for training a text-conditioned model on few captions: the same motion described in
// other words, so that the encoder learns what a caption means rather than how our captions are phrased.
//
// The shared motion capture comes with ~7,000 captions written in a few house styles ("a person walks forward",
// CMU's "walk", HDM05's class names); users prompt in their own words ("an office worker ambles over to the
// printer"), and a model trained on the house styles alone follows few paraphrases
// (docs/results.md on the GPU-trained default and the L_acc sweep). Each word of a
// caption is, independently:
//   - replaced, with probability `swap`, by one of its `neighbours` nearest words in the GloVe space (cosine
//     similarity at least `min_similarity`, among the `search_words` most frequent words): "walks" -> "walking",
//     "strolls", "walked"; "slowly" -> "quickly" also happens, as word vectors put antonyms close: the rate
//     keeps most words, and the motion still anchors the meaning;
//   - dropped, with probability `dropout` (never the last word left).
// Two things are never reworded, as word vectors put opposites side by side ("up" next to "down"): a direction
// word (up, down, left, right, forward, backward, ...) is never swapped, and a rewording that names another
// activity than the caption (motion/activity_names.hpp: "walks" -> "runs", "sits" -> "stands") is dropped for
// the caption as it was.
// Punctuation and words outside the vocabulary pass unchanged. The caption is rebuilt from its lower-case tokens
// (word_tokenizer.hpp), which is what the GloVe encoder reads anyway.
#pragma once
#include <cstdint>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

#include "text/word_vectors.hpp"

namespace t2imu {

struct CaptionAugmentOptions {
    double swap = 0, dropout = 0;  // per-word probabilities, [0, 1)
    int neighbours = 5;            // nearest words a swap chooses from, >= 1
    double min_similarity = 0.6;   // cosine, (0, 1)
    int search_words = 30000;      // the most frequent words searched for neighbours
    bool enabled() const { return swap > 0 || dropout > 0; }
    // Throws Error naming `where` and the key ("augment.swap") for a value out of range.
    void validate(const std::string& where) const;
};

class CaptionAugmenter {
public:
    // Precomputes the neighbours of every word of `captions` (the training captions); other words are
    // looked up and cached on first use.
    CaptionAugmenter(const WordVectors& vectors, const CaptionAugmentOptions& options,
                     const std::vector<std::string>& captions);

    std::string augment(const std::string& caption, std::mt19937_64& rng);
    const std::vector<int>& neighbours_of(int word);  // nearest first, the word itself excluded

private:
    const WordVectors& vectors_;
    CaptionAugmentOptions options_;
    std::vector<float> unit_;  // [search_words, kDims], unit-length rows
    std::unordered_map<int, std::vector<int>> neighbours_;
};

}  // namespace t2imu
