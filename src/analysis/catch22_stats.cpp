// Statistics shared by several catch22 features.
#include <algorithm>
#include <cmath>
#include <complex>

#include "analysis/catch22_features.hpp"
#include "core/signal/fft.hpp"

namespace t2imu::catch22_detail {

double mean(const Series& x) {
    double sum = 0.0;
    for (double v : x) sum += v;
    return sum / static_cast<double>(x.size());
}

double sample_std(const Series& x) {
    const double m = mean(x);
    double ss = 0.0;
    for (double v : x) ss += (v - m) * (v - m);
    return std::sqrt(ss / static_cast<double>(x.size() - 1));
}

Series autocorrelation(const Series& x) {
    const std::size_t n = x.size();
    const double m = mean(x);
    // Padding to at least 2n keeps the circular correlation of the FFT from wrapping around.
    std::vector<std::complex<double>> f(next_power_of_two(2 * n));
    for (std::size_t t = 0; t < n; ++t) f[t] = x[t] - m;
    fft_in_place(f);
    for (auto& c : f) c = std::norm(c);
    fft_in_place(f, true);
    Series acf(n);
    for (std::size_t k = 0; k < n; ++k) acf[k] = f[k].real() / f[0].real();
    return acf;
}

std::size_t first_zero_crossing(const Series& acf) {
    for (std::size_t k = 1; k < acf.size(); ++k)
        if (acf[k] <= 0.0) return k;
    return acf.size();
}

// Quantile with MATLAB's convention (the one hctsa relies on): the sorted values sit at the probabilities
// (i - 0.5) / n, linearly interpolated between, and clamped to the extremes outside.
static double quantile_sorted(const Series& sorted, double p) {
    const double n = static_cast<double>(sorted.size());
    const double position = n * p - 0.5;  // 0-based
    if (position <= 0.0) return sorted.front();
    if (position >= n - 1.0) return sorted.back();
    const std::size_t below = static_cast<std::size_t>(std::floor(position));
    const double frac = position - static_cast<double>(below);
    return sorted[below] + frac * (sorted[below + 1] - sorted[below]);
}

std::vector<int> coarse_grain_quantile(const Series& x, int num_groups) {
    Series sorted = x;
    std::sort(sorted.begin(), sorted.end());
    Series thresholds(num_groups + 1);
    for (int g = 0; g <= num_groups; ++g) thresholds[g] = quantile_sorted(sorted, static_cast<double>(g) / num_groups);
    thresholds[0] -= 1.0;  // the minimum itself belongs to the first group
    std::vector<int> symbols(x.size(), 0);
    for (std::size_t t = 0; t < x.size(); ++t)
        for (int g = 1; g <= num_groups; ++g)
            if (x[t] > thresholds[g - 1] && x[t] <= thresholds[g]) {
                symbols[t] = g;
                break;
            }
    return symbols;
}

void linear_fit(const Series& x, const Series& y, double& slope, double& intercept) {
    const double mx = mean(x), my = mean(y);
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
    }
    slope = sxy / sxx;
    intercept = my - slope * mx;
}

}  // namespace t2imu::catch22_detail
