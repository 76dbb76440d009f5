// catch22_spectral.cpp: SP_Summaries_welch_rect_area_5_1 and SP_Summaries_welch_rect_centroid: Parseval's
// theorem, a cosine on an exact frequency bin, and the reference outputs.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analysis/catch22_features.hpp"
#include "catch22_reference.hpp"

using namespace t2imu::catch22_detail;
using t2imu::test::Catch22Reference;

namespace {
Series cosine_on_bin(int n, int bin) {
    Series x;
    for (int t = 0; t < n; ++t) x.push_back(std::cos(2 * M_PI * bin * t / n));
    return x;
}
}  // namespace

TEST(Catch22Spectral, LowFrequencyAreaOfACosineOnABin) {
    // n = 64: 33 one-sided frequencies of step 2 pi / 64; the lowest fifth is bins 0..5. By Parseval the whole
    // spectrum integrates to the mean square, 1/2 for a cosine; all of it sits on the cosine's bin.
    EXPECT_NEAR(welch_rect_area_5_1(cosine_on_bin(64, 3)), 0.5, 1e-12);
    EXPECT_NEAR(welch_rect_area_5_1(cosine_on_bin(64, 10)), 0.0, 1e-12);
}

TEST(Catch22Spectral, CentroidOfACosineIsItsFrequency) {
    for (int bin : {2, 7, 20})
        EXPECT_NEAR(welch_rect_centroid(cosine_on_bin(64, bin)), bin * 2 * M_PI / 64, 1e-12) << bin;
}

TEST(Catch22Spectral, WhiteNoiseHasAFifthOfItsPowerInTheLowestFifth) {
    // Parseval: with every frequency below the Nyquist one counted, the area is about the mean square (exactly
    // for n a power of two); white noise spreads it evenly, so the lowest fifth (6 of 33 bins, the DC bin
    // counted once) holds about 5.5 / 32 of it.
    std::mt19937 rng(11);
    std::normal_distribution<double> g;
    double area = 0, mean_square = 0;
    for (int rep = 0; rep < 200; ++rep) {
        Series x(64);
        for (double& v : x) v = g(rng);
        area += welch_rect_area_5_1(x);
        for (double v : x) mean_square += v * v / 64;
    }
    EXPECT_NEAR(area / mean_square, 5.5 / 32, 0.02);
}

TEST(Catch22Spectral, MatchesTheReference) {
    std::vector<Catch22Reference> cases;
    CATCH22_REFERENCE_OR_SKIP(cases);
    using t2imu::test::expect_catch22_feature;
    EXPECT_GE(expect_catch22_feature(cases, "SP_Summaries_welch_rect_area_5_1",
                                     [](const Catch22Reference& c) { return welch_rect_area_5_1(c.z); }),
              25);
    EXPECT_GE(expect_catch22_feature(cases, "SP_Summaries_welch_rect_centroid",
                                     [](const Catch22Reference& c) { return welch_rect_centroid(c.z); }),
              25);
}
