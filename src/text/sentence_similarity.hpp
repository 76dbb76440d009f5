// Sentence similarity without a trained sentence encoder: SIF embeddings (Arora, Liang & Ma 2017, "A simple but
// tough-to-beat baseline for sentence embeddings") over GloVe vectors. A sentence is the mean of its known
// words' vectors weighted by a / (a + p(w)) (a = 1e-3; p(w) from the word's frequency rank, word_vectors.hpp),
// so frequent words ("a", "the", "person") count little; the corpus's first principal component (what all
// sentences share) is then projected out. Unknown words are skipped; a sentence with none embeds to zero.
// The evaluation uses it to put captions into activity categories (the paper used all-MiniLM-L6-v2).
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "text/word_vectors.hpp"

namespace t2imu {

class SifEncoder {
public:
    explicit SifEncoder(const WordVectors& vectors, double a = 1e-3);

    // The weighted mean, without the common component.
    Eigen::VectorXd embed(const std::string& sentence) const;
    // Learns the common component from a corpus (several hundred sentences or more; fewer give a noisy one).
    void fit_common_component(const std::vector<std::string>& corpus);
    const Eigen::VectorXd& common_component() const { return common_; }

private:
    Eigen::VectorXd weighted_mean(const std::string& sentence) const;

    const WordVectors& vectors_;
    double a_;
    Eigen::VectorXd common_;  // unit vector, or empty
};

double cosine_similarity(const Eigen::VectorXd& a, const Eigen::VectorXd& b);  // 0 when either is zero

// For each query, the corpus sentence most similar to it (cosine of SIF embeddings): how close a prompt set's
// wording comes to the captions a model learned from. index = corpus.size() when the corpus is empty.
struct NearestSentence {
    size_t index = 0;
    double similarity = 0;
};
std::vector<NearestSentence> nearest_sentences(const SifEncoder& sif, const std::vector<std::string>& corpus,
                                               const std::vector<std::string>& queries);

}  // namespace t2imu
