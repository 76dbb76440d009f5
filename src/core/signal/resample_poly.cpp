#include "core/signal/resample_poly.hpp"

#include <cmath>
#include <numeric>

#include "core/error.hpp"

namespace t2imu {

namespace {

double bessel_i0(double x) {
    // Power series; converges quickly for the arguments a Kaiser window needs (|x| <= beta).
    double sum = 1, term = 1;
    for (int k = 1; k < 200 && term > 1e-17 * sum; ++k) {
        term *= (x / (2 * k)) * (x / (2 * k));
        sum += term;
    }
    return sum;
}

double sinc(double x) { return x == 0 ? 1.0 : std::sin(M_PI * x) / (M_PI * x); }

}  // namespace

std::vector<double> kaiser_lowpass(int taps, double cutoff, double beta) {
    std::vector<double> h(static_cast<size_t>(taps));
    const double alpha = 0.5 * (taps - 1);
    double sum = 0;
    for (int n = 0; n < taps; ++n) {
        const double m = n - alpha;
        const double r = taps > 1 ? (2.0 * n / (taps - 1) - 1.0) : 0.0;
        const double window = bessel_i0(beta * std::sqrt(std::max(0.0, 1 - r * r))) / bessel_i0(beta);
        h[static_cast<size_t>(n)] = cutoff * sinc(cutoff * m) * window;
        sum += h[static_cast<size_t>(n)];
    }
    for (double& v : h) v /= sum;
    return h;
}

std::vector<double> resample_poly(const std::vector<double>& x, int up, int down) {
    if (up < 1 || down < 1) throw Error("resample_poly", "rates", "positive integer up and down factors");
    if (x.size() < 2) throw Error("resample_poly", "samples", "at least 2");
    const int g = std::gcd(up, down);
    up /= g;
    down /= g;
    if (up == 1 && down == 1) return x;
    const long n_in = static_cast<long>(x.size());
    const long n_out = (n_in * up + down - 1) / down;
    const int max_rate = std::max(up, down), half_len = 10 * max_rate;
    std::vector<double> h = kaiser_lowpass(2 * half_len + 1, 1.0 / max_rate, 5.0);
    for (double& v : h) v *= up;
    // Leading zeros put output sample i at input time i * down / up.
    const int pre_pad = down - half_len % down;
    h.insert(h.begin(), static_cast<size_t>(pre_pad), 0.0);
    const long pre_remove = (half_len + pre_pad) / down;
    const double slope = (x.back() - x.front()) / static_cast<double>(n_in - 1);
    auto extended = [&](long i) {
        if (i < 0) return x.front() + static_cast<double>(i) * slope;
        if (i >= n_in) return x.back() + static_cast<double>(i - n_in + 1) * slope;
        return x[static_cast<size_t>(i)];
    };
    std::vector<double> y(static_cast<size_t>(n_out));
    for (long i = 0; i < n_out; ++i) {
        const long k = (i + pre_remove) * down;  // index in the upsampled signal
        double acc = 0;
        for (long j = k % up; j < static_cast<long>(h.size()); j += up)  // only taps that hit input samples
            acc += h[static_cast<size_t>(j)] * extended((k - j) / up);
        y[static_cast<size_t>(i)] = acc;
    }
    return y;
}

}  // namespace t2imu
