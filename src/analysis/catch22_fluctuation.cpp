// Fluctuation analysis: SC_FluctAnal_2_rsrangefit_50_1_logi_prop_r1 and SC_FluctAnal_2_dfa_50_1_2_logi_prop_r1.
#include <algorithm>
#include <cmath>

#include "analysis/catch22_features.hpp"

namespace t2imu::catch22_detail {

namespace {
enum class Fluctuation { RescaledRange, Dfa };

// The fluctuation of one window of the integrated series after removing its least-squares line: its range
// (rescaled-range analysis) or its root-mean-square (detrended fluctuation analysis).
double window_fluctuation(const Series& window, Fluctuation kind) {
    Series time(window.size());
    for (std::size_t i = 0; i < window.size(); ++i) time[i] = static_cast<double>(i + 1);
    double slope, intercept;
    linear_fit(time, window, slope, intercept);
    double lo = INFINITY, hi = -INFINITY, ss = 0.0;
    for (std::size_t i = 0; i < window.size(); ++i) {
        const double r = window[i] - (slope * time[i] + intercept);
        lo = std::min(lo, r);
        hi = std::max(hi, r);
        ss += r * r;
    }
    return kind == Fluctuation::RescaledRange ? hi - lo : std::sqrt(ss / static_cast<double>(window.size()));
}

// Sum of the Euclidean norms of the residuals of straight-line fits to points [0, split] and [split, end).
double two_line_error(const Series& log_tau, const Series& log_f, std::size_t split) {
    double error = 0.0;
    for (auto [first, last] : {std::pair<std::size_t, std::size_t>{0, split + 1}, {split, log_tau.size()}}) {
        const Series t(log_tau.begin() + first, log_tau.begin() + last);
        const Series f(log_f.begin() + first, log_f.begin() + last);
        double slope, intercept, ss = 0.0;
        linear_fit(t, f, slope, intercept);
        for (std::size_t i = 0; i < t.size(); ++i) ss += std::pow(f[i] - (slope * t[i] + intercept), 2);
        error += std::sqrt(ss);
    }
    return error;
}

// hctsa's SC_FluctAnal with q = 2, 50 log-spaced window sizes from 5 to n/2 (rounded, duplicates dropped),
// non-overlapping windows of the cumulative sum of every lag-th sample. F(tau) is the root-mean-square of the window
// fluctuations. Two straight lines are fitted to log F against log tau, split where their summed residual norms are
// least (each with at least 6 points); the output is the share of window sizes in the first (prop_r1).
double fluct_anal_prop_r1(const Series& series, Fluctuation kind, std::size_t lag) {
    Series x;
    for (std::size_t t = 0; t < series.size(); t += lag) x.push_back(series[t]);
    const std::size_t n = x.size(), num_sizes = 50, min_points = 6;
    Series integrated(n);
    double sum = 0.0;
    for (std::size_t t = 0; t < n; ++t) integrated[t] = sum += x[t];
    std::vector<std::size_t> taus;
    // The window sizes span 5 .. half the length of the series before the lag is applied (hctsa sets them up
    // first), so with lag 2 the largest window holds the whole subsampled series.
    const double log_lo = std::log(5.0), log_hi = std::log(std::floor(static_cast<double>(series.size()) / 2.0));
    for (std::size_t i = 0; i < num_sizes; ++i) {
        const double log_tau = log_lo + (log_hi - log_lo) * static_cast<double>(i) / (num_sizes - 1);
        const std::size_t tau = static_cast<std::size_t>(std::lround(std::exp(log_tau)));
        if (taus.empty() || tau != taus.back()) taus.push_back(tau);
    }
    const std::size_t num_taus = taus.size();
    if (num_taus < 2 * min_points) return 0.0;
    Series log_tau(num_taus), log_f(num_taus);
    for (std::size_t i = 0; i < num_taus; ++i) {
        const std::size_t tau = taus[i], num_windows = n / tau;
        double mean_square = 0.0;
        for (std::size_t w = 0; w < num_windows; ++w) {
            const Series window(integrated.begin() + w * tau, integrated.begin() + (w + 1) * tau);
            mean_square += std::pow(window_fluctuation(window, kind), 2) / static_cast<double>(num_windows);
        }
        log_tau[i] = std::log(static_cast<double>(tau));
        log_f[i] = std::log(std::sqrt(mean_square));
    }
    // The split index is 1-based in hctsa: its first line covers points 1..split, the second split..end.
    std::size_t best_split = 0;
    double best_error = INFINITY;
    for (std::size_t split = min_points; split <= num_taus - min_points; ++split) {
        const double error = two_line_error(log_tau, log_f, split - 1);
        if (error < best_error) {
            best_error = error;
            best_split = split;
        }
    }
    return static_cast<double>(best_split) / static_cast<double>(num_taus);
}
}  // namespace

double fluct_anal_rsrangefit_prop_r1(const Series& x) { return fluct_anal_prop_r1(x, Fluctuation::RescaledRange, 1); }
double fluct_anal_dfa_prop_r1(const Series& x) {
    return fluct_anal_prop_r1(x, Fluctuation::Dfa, 2);
}  // "_1_2": k = 1, lag 2

}  // namespace t2imu::catch22_detail
