#include "text/sentence_similarity.hpp"

#include <Eigen/Eigenvalues>

#include "text/word_tokenizer.hpp"

namespace t2imu {

SifEncoder::SifEncoder(const WordVectors& vectors, double a) : vectors_(vectors), a_(a) {}

Eigen::VectorXd SifEncoder::weighted_mean(const std::string& sentence) const {
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(WordVectors::kDims);
    int known = 0;
    for (int i : word_indices(sentence, vectors_)) {
        if (i < 0) continue;
        const double w = a_ / (a_ + vectors_.probability(i));
        sum += w * Eigen::Map<const Eigen::VectorXf>(vectors_.vector(i), WordVectors::kDims).cast<double>();
        ++known;
    }
    return known ? Eigen::VectorXd(sum / known) : sum;
}

Eigen::VectorXd SifEncoder::embed(const std::string& sentence) const {
    Eigen::VectorXd v = weighted_mean(sentence);
    if (common_.size() == v.size()) v -= common_.dot(v) * common_;
    return v;
}

void SifEncoder::fit_common_component(const std::vector<std::string>& corpus) {
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(WordVectors::kDims, WordVectors::kDims);
    for (const std::string& s : corpus) {
        const Eigen::VectorXd v = weighted_mean(s);
        gram += v * v.transpose();  // uncentred, as the paper's TruncatedSVD
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram);
    common_ = eig.eigenvectors().col(WordVectors::kDims - 1);
}

double cosine_similarity(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    const double n = a.norm() * b.norm();
    return n > 0 ? a.dot(b) / n : 0.0;
}

std::vector<NearestSentence> nearest_sentences(const SifEncoder& sif, const std::vector<std::string>& corpus,
                                               const std::vector<std::string>& queries) {
    std::vector<Eigen::VectorXd> embedded;
    embedded.reserve(corpus.size());
    for (const std::string& s : corpus) embedded.push_back(sif.embed(s));
    std::vector<NearestSentence> out;
    for (const std::string& q : queries) {
        const Eigen::VectorXd e = sif.embed(q);
        NearestSentence best{corpus.size(), -2.0};
        for (size_t i = 0; i < embedded.size(); ++i)
            if (const double c = cosine_similarity(e, embedded[i]); c > best.similarity) best = {i, c};
        if (corpus.empty()) best.similarity = 0;
        out.push_back(best);
    }
    return out;
}

}  // namespace t2imu
