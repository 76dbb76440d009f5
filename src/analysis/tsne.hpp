// t-SNE (van der Maaten & Hinton 2008) with the Barnes-Hut approximation (van der Maaten 2014), for the
// paper's real-vs-synthetic feature plots, and the trustworthiness of an embedding (Venna & Kaski 2001).
//
// Settings follow scikit-learn's TSNE, which the paper's figures come from: perplexity 30; affinities from a
// binary search of each point's Gaussian bandwidth (exact: over all points; Barnes-Hut: over its 3 x perplexity
// nearest neighbours, found by brute force), symmetrised and normalised; PCA initialisation scaled so the
// first coordinate has standard deviation 1e-4; early exaggeration 12 for 250 iterations with momentum 0.5,
// then momentum 0.8; learning rate max(N / 12, 50); per-parameter gains (+0.2 / x0.8, at least 0.01); 1000
// iterations; Barnes-Hut angle theta = 0.5 on a quadtree.
#pragma once
#include <Eigen/Core>

namespace t2imu {

using PointMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;  // [N, D]

struct TsneOptions {
    double perplexity = 30;
    double early_exaggeration = 12;
    int exaggeration_iterations = 250, iterations = 1000;
    double theta = 0.5;  // 0 = exact gradients (O(N^2)); Barnes-Hut otherwise
    bool exact = false;  // exact affinities and gradients

    // Throws Error naming --perplexity or --iterations for a value that no data could make valid (not finite,
    // not positive, beyond 10^6); tsne() checks perplexity against the number of points.
    void validate() const;
};  // no seed: PCA initialisation makes the method deterministic

struct TsneResult {
    PointMatrix embedding;     // [N, 2]
    double kl_divergence = 0;  // KL(P || Q) at the end (exact: all pairs; Barnes-Hut: estimated from the tree)
};

TsneResult tsne(const PointMatrix& x, const TsneOptions& options = {});

// 1 - 2 / (n k (2n - 3k - 1)) sum_i sum_{j in U_i} (r(i, j) - k): how far the embedding's k nearest neighbours
// are from the original's (1 = all kept). scikit-learn's trustworthiness (Euclidean, k = n_neighbors).
double trustworthiness(const PointMatrix& x, const PointMatrix& embedding, int k = 5);

}  // namespace t2imu
