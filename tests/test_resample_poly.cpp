#include <gtest/gtest.h>

#include <cmath>

#include "core/signal/resample_poly.hpp"

using namespace t2imu;

TEST(ResamplePoly, KaiserLowpassHasUnitGainAndSymmetry) {
    const std::vector<double> h = kaiser_lowpass(81, 0.25, 5.0);
    double sum = 0;
    for (double v : h) sum += v;
    EXPECT_NEAR(sum, 1.0, 1e-12);
    for (size_t i = 0; i < h.size(); ++i) EXPECT_NEAR(h[i], h[h.size() - 1 - i], 1e-15);
    // Pass band flat, stop band beyond the 0.25 cut-off (plus the transition width) down by about 50 dB.
    auto gain = [&](double f) {  // f relative to Nyquist
        double re = 0, im = 0;
        for (size_t n = 0; n < h.size(); ++n) {
            re += h[n] * std::cos(M_PI * f * static_cast<double>(n));
            im -= h[n] * std::sin(M_PI * f * static_cast<double>(n));
        }
        return std::hypot(re, im);
    };
    EXPECT_NEAR(gain(0.1), 1.0, 2e-3);
    EXPECT_NEAR(gain(0.25), 0.5, 0.02);  // the cut-off sits at half amplitude
    for (double f = 0.34; f <= 1.0; f += 0.01) EXPECT_LT(gain(f), 3e-3) << f;
}

TEST(ResamplePoly, LinesPassExactlyAndSlowSinesKeepTheirShape) {
    std::vector<double> ramp(400), sine(400);
    for (int i = 0; i < 400; ++i) {
        ramp[static_cast<size_t>(i)] = 9.81 + 0.01 * i;                       // gravity plus a drift
        sine[static_cast<size_t>(i)] = std::sin(2 * M_PI * 2.0 * i / 200.0);  // 2 Hz at 200 Hz
    }
    const std::vector<double> r = resample_poly(ramp, 1, 4), s = resample_poly(sine, 1, 4);
    ASSERT_EQ(r.size(), 100u);
    for (size_t i = 0; i < r.size(); ++i) EXPECT_NEAR(r[i], ramp[4 * i], 1e-9);  // line padding: no edge ringing
    for (size_t i = 10; i + 10 < s.size(); ++i) EXPECT_NEAR(s[i], sine[4 * i], 2e-3);
    EXPECT_EQ(resample_poly(ramp, 2, 3).size(), 267u);  // ceil(400 * 2 / 3)
}
