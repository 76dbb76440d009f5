// The radix-2 FFT: powers of two, a delta and a complex exponential, agreement with the direct DFT sum, the
// inverse round trip, and refused lengths.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>

#include "core/error.hpp"
#include "core/signal/fft.hpp"

using namespace t2imu;
using cd = std::complex<double>;

TEST(Fft, NextPowerOfTwo) {
    EXPECT_EQ(next_power_of_two(0), 1u);
    EXPECT_EQ(next_power_of_two(1), 1u);
    EXPECT_EQ(next_power_of_two(5), 8u);
    EXPECT_EQ(next_power_of_two(8), 8u);
    EXPECT_EQ(next_power_of_two(1025), 2048u);
}

TEST(Fft, DeltaAndExponential) {
    // A delta at t = 0 has a flat spectrum of ones.
    std::vector<cd> d(16, 0.0);
    d[0] = 1.0;
    fft_in_place(d);
    for (const cd& v : d) EXPECT_NEAR(std::abs(v - cd(1, 0)), 0.0, 1e-15);
    // exp(2 pi i 3 t / 16): all of it (16) in bin 3 with the forward sign convention exp(-2 pi i k t / N).
    std::vector<cd> e(16);
    for (int t = 0; t < 16; ++t) e[t] = std::polar(1.0, 2 * M_PI * 3 * t / 16);
    fft_in_place(e);
    for (int k = 0; k < 16; ++k) EXPECT_NEAR(std::abs(e[k] - cd(k == 3 ? 16 : 0, 0)), 0.0, 1e-12) << k;
}

TEST(Fft, MatchesTheDirectSumAndInvertsWithOneOverN) {
    std::mt19937 rng(7);
    std::normal_distribution<double> g;
    for (size_t n : {1u, 2u, 4u, 32u, 256u}) {
        std::vector<cd> x(n);
        for (cd& v : x) v = cd(g(rng), g(rng));
        std::vector<cd> f = x;
        fft_in_place(f);
        for (size_t k = 0; k < n; ++k) {
            cd direct = 0;
            for (size_t t = 0; t < n; ++t) direct += x[t] * std::polar(1.0, -2 * M_PI * double(k * t % n) / double(n));
            EXPECT_NEAR(std::abs(f[k] - direct), 0.0, 1e-10 * double(n)) << "n " << n << " bin " << k;
        }
        fft_in_place(f, true);  // no 1/N factor
        for (size_t t = 0; t < n; ++t) EXPECT_NEAR(std::abs(f[t] / double(n) - x[t]), 0.0, 1e-12) << "n " << n;
    }
}

TEST(Fft, RefusesLengthsThatAreNotPowersOfTwo) {
    for (size_t n : {0u, 3u, 6u, 100u}) {
        std::vector<cd> x(n);
        try {
            fft_in_place(x);
            ADD_FAILURE() << "length " << n << " accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("length"), std::string::npos) << e.what();
        }
    }
}
