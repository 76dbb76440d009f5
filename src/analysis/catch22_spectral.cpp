// Spectral features: SP_Summaries_welch_rect_area_5_1 and SP_Summaries_welch_rect_centroid.
#include <cmath>
#include <complex>

#include "analysis/catch22_features.hpp"
#include "core/signal/fft.hpp"

namespace t2imu::catch22_detail {

namespace {
// A one-sided power spectral density over angular frequency (rad/sample): Welch's estimate with a single
// rectangular window as long as the series, zero-padded to the next power of two.
struct Spectrum {
    Series power;     // density at each frequency
    double step = 0;  // frequency spacing (rad/sample)
};

Spectrum welch_rect(const Series& x) {
    const std::size_t n = x.size(), nfft = next_power_of_two(n);
    std::vector<std::complex<double>> f(nfft);
    for (std::size_t t = 0; t < n; ++t) f[t] = x[t];
    fft_in_place(f);
    Spectrum s;
    s.step = 2.0 * M_PI / static_cast<double>(nfft);
    const std::size_t num_freqs = nfft / 2 + 1;
    s.power.resize(num_freqs);
    for (std::size_t k = 0; k < num_freqs; ++k) {
        // One-sided: every frequency but DC and Nyquist carries its negative twin's power too.
        const double fold = (k == 0 || k == nfft / 2) ? 1.0 : 2.0;
        s.power[k] = fold * std::norm(f[k]) / (2.0 * M_PI * static_cast<double>(n));
    }
    return s;
}
}  // namespace

// SP_Summaries_welch_rect_area_5_1: the power in the lowest fifth of the frequencies.
double welch_rect_area_5_1(const Series& x) {
    const Spectrum s = welch_rect(x);
    double area = 0.0;
    for (std::size_t k = 0; k < s.power.size() / 5; ++k) area += s.power[k] * s.step;
    return area;
}

// SP_Summaries_welch_rect_centroid: the frequency below which half of the power lies.
double welch_rect_centroid(const Series& x) {
    const Spectrum s = welch_rect(x);
    double total = 0.0;
    for (double p : s.power) total += p * s.step;
    double cumulative = 0.0;
    for (std::size_t k = 0; k < s.power.size(); ++k) {
        cumulative += s.power[k] * s.step;
        if (cumulative > 0.5 * total) return static_cast<double>(k) * s.step;
    }
    return static_cast<double>(s.power.size() - 1) * s.step;
}

}  // namespace t2imu::catch22_detail
