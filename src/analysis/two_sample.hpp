// How far synthetic IMU data is from real data, in numbers (beyond the paper's t-SNE pictures).
//
// Classifier two-sample test (Lopez-Paz & Oquab 2017): label real windows 0 and synthetic ones 1, train a
// classifier on features (catch22 per channel) and report its cross-validated balanced accuracy: 0.5 means the
// two sets cannot be told apart, 1.0 that they are fully separable. The classifier is L2-regularised logistic
// regression on standardised features (statistics of the training folds only; columns with NaN in a fold's
// training data are dropped), fitted by Newton's method: convex, deterministic, no tuning.
// Per-feature distances: the 1-Wasserstein distance (in the feature's units) and the Kolmogorov-Smirnov
// statistic of the two empirical distributions.
#pragma once
#include <cstdint>
#include <vector>

#include "analysis/tsne.hpp"

namespace t2imu {

struct TwoSampleResult {
    double balanced_accuracy = 0;  // mean over folds
    std::vector<double> fold_accuracy;
};

// Rows are samples, columns features (NaN allowed). Folds are stratified and seeded.
TwoSampleResult classifier_two_sample_test(const PointMatrix& real, const PointMatrix& synthetic, int folds = 5,
                                           uint64_t seed = 0, double l2 = 1.0);

double wasserstein_1d(std::vector<double> a, std::vector<double> b);  // NaNs are dropped
double ks_statistic(std::vector<double> a, std::vector<double> b);    // sup |F_a - F_b|; NaNs dropped

}  // namespace t2imu
