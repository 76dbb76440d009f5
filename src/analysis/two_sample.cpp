#include "analysis/two_sample.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "core/error.hpp"

namespace t2imu {

namespace {

std::vector<double> finite(std::vector<double> v) {
    v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
    std::sort(v.begin(), v.end());
    return v;
}

// Newton's method on the L2-regularised logistic loss; x has a leading column of ones (not penalised).
Eigen::VectorXd fit_logistic(const Eigen::MatrixXd& x, const Eigen::VectorXd& y, const Eigen::VectorXd& weight,
                             double l2) {
    Eigen::VectorXd w = Eigen::VectorXd::Zero(x.cols());
    Eigen::VectorXd penalty = Eigen::VectorXd::Constant(x.cols(), l2);
    penalty[0] = 0;
    for (int it = 0; it < 50; ++it) {
        const Eigen::VectorXd p = (1.0 + (-(x * w)).array().exp()).inverse().matrix();
        const Eigen::VectorXd grad =
            x.transpose() * (weight.array() * (p - y).array()).matrix() + penalty.cwiseProduct(w);
        const Eigen::VectorXd s = weight.array() * p.array() * (1 - p.array());
        Eigen::MatrixXd hessian = x.transpose() * s.asDiagonal() * x;
        hessian.diagonal() += penalty + Eigen::VectorXd::Constant(x.cols(), 1e-9);
        const Eigen::VectorXd step = hessian.ldlt().solve(grad);
        w -= step;
        if (step.norm() < 1e-9) break;
    }
    return w;
}

}  // namespace

TwoSampleResult classifier_two_sample_test(const PointMatrix& real, const PointMatrix& synthetic, int folds,
                                           uint64_t seed, double l2) {
    if (real.cols() != synthetic.cols())
        throw Error("two-sample test", "features", std::to_string(real.cols()), std::to_string(synthetic.cols()));
    if (real.rows() < folds || synthetic.rows() < folds || folds < 2)
        throw Error("two-sample test", "samples",
                    "at least " + std::to_string(std::max(folds, 2)) + " per set, one per fold",
                    std::to_string(real.rows()) + " real, " + std::to_string(synthetic.rows()) + " synthetic");
    const Eigen::Index n = real.rows() + synthetic.rows(), d = real.cols();
    PointMatrix all(n, d);
    all << real, synthetic;
    std::vector<int> label(static_cast<size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) label[static_cast<size_t>(i)] = i >= real.rows();
    // Stratified folds: each class shuffled and dealt round robin.
    std::vector<int> fold(static_cast<size_t>(n));
    std::mt19937_64 rng(seed);
    for (int cls = 0; cls < 2; ++cls) {
        std::vector<Eigen::Index> idx;
        for (Eigen::Index i = 0; i < n; ++i)
            if (label[static_cast<size_t>(i)] == cls) idx.push_back(i);
        std::shuffle(idx.begin(), idx.end(), rng);
        for (size_t k = 0; k < idx.size(); ++k)
            fold[static_cast<size_t>(idx[k])] = static_cast<int>(k % static_cast<size_t>(folds));
    }
    TwoSampleResult result;
    for (int f = 0; f < folds; ++f) {
        std::vector<Eigen::Index> train, test;
        for (Eigen::Index i = 0; i < n; ++i) (fold[static_cast<size_t>(i)] == f ? test : train).push_back(i);
        // Standardise on the training fold; keep the columns that are finite there and not constant.
        std::vector<Eigen::Index> cols;
        std::vector<double> mean, sd;
        for (Eigen::Index c = 0; c < d; ++c) {
            double s = 0, s2 = 0;
            bool ok = true;
            for (Eigen::Index i : train) {
                const double v = all(i, c);
                ok = ok && std::isfinite(v);
                s += v;
                s2 += v * v;
            }
            const double m = s / static_cast<double>(train.size()),
                         var = s2 / static_cast<double>(train.size()) - m * m;
            if (!ok || !(var > 1e-12)) continue;
            cols.push_back(c);
            mean.push_back(m);
            sd.push_back(std::sqrt(var));
        }
        const auto design = [&](const std::vector<Eigen::Index>& rows) {
            Eigen::MatrixXd x(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size()) + 1);
            for (size_t r = 0; r < rows.size(); ++r) {
                x(static_cast<Eigen::Index>(r), 0) = 1;
                for (size_t c = 0; c < cols.size(); ++c) {
                    const double v = all(rows[r], cols[c]);
                    x(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c) + 1) =
                        std::isfinite(v) ? (v - mean[c]) / sd[c] : 0.0;
                }
            }
            return x;
        };
        const Eigen::MatrixXd xt = design(train);
        Eigen::VectorXd y(xt.rows()), weight(xt.rows());
        double count[2] = {0, 0};
        for (size_t r = 0; r < train.size(); ++r) count[label[static_cast<size_t>(train[r])]] += 1;
        for (size_t r = 0; r < train.size(); ++r) {
            const int l = label[static_cast<size_t>(train[r])];
            y[static_cast<Eigen::Index>(r)] = l;
            weight[static_cast<Eigen::Index>(r)] =
                static_cast<double>(train.size()) / (2 * count[l]);  // balanced classes
        }
        const Eigen::VectorXd w = fit_logistic(xt, y, weight, l2);
        const Eigen::VectorXd score = design(test) * w;
        double correct[2] = {0, 0}, total[2] = {0, 0};
        for (size_t r = 0; r < test.size(); ++r) {
            const int l = label[static_cast<size_t>(test[r])];
            total[l] += 1;
            correct[l] += (score[static_cast<Eigen::Index>(r)] > 0) == (l == 1);
        }
        result.fold_accuracy.push_back((correct[0] / total[0] + correct[1] / total[1]) / 2);
    }
    result.balanced_accuracy = std::accumulate(result.fold_accuracy.begin(), result.fold_accuracy.end(), 0.0) / folds;
    return result;
}

double wasserstein_1d(std::vector<double> a, std::vector<double> b) {
    a = finite(std::move(a));
    b = finite(std::move(b));
    if (a.empty() || b.empty()) return std::nan("");
    // Integral of |F_a - F_b| over the merged support.
    std::vector<double> points = a;
    points.insert(points.end(), b.begin(), b.end());
    std::sort(points.begin(), points.end());
    double total = 0;
    for (size_t k = 0; k + 1 < points.size(); ++k) {
        const double x = points[k];
        const double fa =
            static_cast<double>(std::upper_bound(a.begin(), a.end(), x) - a.begin()) / static_cast<double>(a.size());
        const double fb =
            static_cast<double>(std::upper_bound(b.begin(), b.end(), x) - b.begin()) / static_cast<double>(b.size());
        total += std::fabs(fa - fb) * (points[k + 1] - x);
    }
    return total;
}

double ks_statistic(std::vector<double> a, std::vector<double> b) {
    a = finite(std::move(a));
    b = finite(std::move(b));
    if (a.empty() || b.empty()) return std::nan("");
    double best = 0;
    for (const std::vector<double>* side : {&a, &b})
        for (double x : *side) {
            const double fa = static_cast<double>(std::upper_bound(a.begin(), a.end(), x) - a.begin()) /
                              static_cast<double>(a.size());
            const double fb = static_cast<double>(std::upper_bound(b.begin(), b.end(), x) - b.begin()) /
                              static_cast<double>(b.size());
            best = std::max(best, std::fabs(fa - fb));
        }
    return best;
}

}  // namespace t2imu
