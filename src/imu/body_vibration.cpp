#include "imu/body_vibration.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>

#include "core/signal/fft.hpp"

namespace t2imu {

using Eigen::Vector3d;

namespace {

// Centred moving mean over `width` samples, the edge samples repeated beyond the ends.
std::vector<double> moving_mean(const std::vector<double>& x, size_t width) {
    const auto n = static_cast<std::ptrdiff_t>(x.size());
    const auto w = static_cast<std::ptrdiff_t>(width);
    std::vector<double> out(x.size());
    for (std::ptrdiff_t k = 0; k < n; ++k) {
        double sum = 0;
        for (std::ptrdiff_t j = k - w / 2; j < k - w / 2 + w; ++j)
            sum += x[static_cast<size_t>(std::clamp<std::ptrdiff_t>(j, 0, n - 1))];
        out[static_cast<size_t>(k)] = sum / static_cast<double>(w);
    }
    return out;
}

// The motion's local rms level (m/s^2): acceleration apart from its 1 s moving mean, rms over 1 s.
std::vector<double> motion_level(const std::vector<Vector3d>& acc, double rate_hz) {
    const size_t width = std::max<size_t>(1, static_cast<size_t>(std::lround(rate_hz)));
    std::vector<double> squared(acc.size(), 0.0);
    for (int axis = 0; axis < 3; ++axis) {
        std::vector<double> x(acc.size());
        for (size_t k = 0; k < acc.size(); ++k) x[k] = acc[k][axis];
        const std::vector<double> slow = moving_mean(x, width);
        for (size_t k = 0; k < acc.size(); ++k) squared[k] += (x[k] - slow[k]) * (x[k] - slow[k]);
    }
    std::vector<double> level = moving_mean(squared, width);
    for (double& v : level) v = std::sqrt(v);
    return level;
}

// n samples of Gaussian noise with the band's magnitude response (body_vibration.hpp), sd 1.
std::vector<double> band_noise(size_t n, double rate_hz, const BodyVibration& v, std::mt19937_64& rng) {
    const size_t m = next_power_of_two(n);
    std::normal_distribution<double> normal;
    std::vector<std::complex<double>> x(m);
    for (auto& c : x) c = normal(rng);
    fft_in_place(x);
    for (size_t k = 0; k < m; ++k) {
        const double f = static_cast<double>(std::min(k, m - k)) * rate_hz / static_cast<double>(m);
        const double lo = std::pow(f / v.low_hz, 4), hi = std::pow(f / v.high_hz, 4);
        x[k] *= lo / (1 + lo) / (1 + hi);
    }
    fft_in_place(x, true);
    std::vector<double> out(n);
    double mean = 0, power = 0;
    for (size_t k = 0; k < n; ++k) mean += (out[k] = x[k].real()) / static_cast<double>(n);
    for (double& s : out) power += (s - mean) * (s - mean) / static_cast<double>(n);
    const double scale = power > 0 ? 1 / std::sqrt(power) : 0;
    for (double& s : out) s = (s - mean) * scale;
    return out;
}

}  // namespace

void add_body_vibration(const BodyVibration& vibration, uint64_t seed, ImuSignals* s) {
    if (!vibration.enabled() || s->acc.size() < 2) return;
    const std::vector<double> level = motion_level(s->acc, s->rate_hz);
    std::mt19937_64 rng(seed);
    for (int axis = 0; axis < 3; ++axis) {
        const std::vector<double> noise = band_noise(s->acc.size(), s->rate_hz, vibration, rng);
        for (size_t k = 0; k < s->acc.size(); ++k) s->acc[k][axis] += vibration.gain * level[k] * noise[k];
    }
}

}  // namespace t2imu
