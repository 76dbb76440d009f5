// catch22_stats.cpp: the statistics the catch22 features share (analysis/catch22_features.hpp): mean, sample
// standard deviation, the FFT autocorrelation against the direct sum, the first zero crossing, MATLAB-quantile
// coarse graining and the least-squares line.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analysis/catch22_features.hpp"
#include "catch22_reference.hpp"

using namespace t2imu::catch22_detail;

TEST(Catch22Stats, MeanAndSampleStandardDeviation) {
    EXPECT_DOUBLE_EQ(mean({1, 2, 3, 4}), 2.5);
    // Deviations -1.5, -0.5, 0.5, 1.5: squares sum to 5, over n - 1 = 3.
    EXPECT_DOUBLE_EQ(sample_std({1, 2, 3, 4}), std::sqrt(5.0 / 3.0));
    EXPECT_DOUBLE_EQ(sample_std({7, 7, 7}), 0.0);
}

TEST(Catch22Stats, AutocorrelationOfAHandComputedSeries) {
    // x = 1, 2, 3: deviations -1, 0, 1; r(0) = 2, r(1) = (-1)(0) + (0)(1) = 0, r(2) = (-1)(1) = -1.
    const Series acf = autocorrelation({1, 2, 3});
    ASSERT_EQ(acf.size(), 3u);
    EXPECT_NEAR(acf[0], 1.0, 1e-15);
    EXPECT_NEAR(acf[1], 0.0, 1e-15);
    EXPECT_NEAR(acf[2], -0.5, 1e-15);
}

TEST(Catch22Stats, AutocorrelationIsLinearNotCircular) {
    // Lengths around powers of two: the FFT pads; a circular correlation would differ from the direct sum.
    std::mt19937 rng(3);
    std::normal_distribution<double> g;
    for (size_t n : {10u, 16u, 17u, 100u, 128u}) {
        Series x(n);
        for (double& v : x) v = g(rng) + 0.05 * static_cast<double>(&v - x.data());
        const Series fast = autocorrelation(x), direct = t2imu::test::direct_autocorrelation(x);
        ASSERT_EQ(fast.size(), n);
        for (size_t k = 0; k < n; ++k) EXPECT_NEAR(fast[k], direct[k], 1e-12) << "n " << n << " lag " << k;
    }
}

TEST(Catch22Stats, FirstZeroCrossing) {
    EXPECT_EQ(first_zero_crossing({1, 0.5, 0.1, -0.2, 0.3}), 3u);
    EXPECT_EQ(first_zero_crossing({1, 0.5, 0.0, 0.4}), 2u);  // reaching zero counts
    EXPECT_EQ(first_zero_crossing({1, 0.9, 0.8}), 3u);       // never: n
}

TEST(Catch22Stats, CoarseGrainByMatlabQuantiles) {
    // Six values: MATLAB's quantiles put sorted value i at (i - 0.5) / 6, so the 1/3 quantile is 2.5 and the
    // 2/3 quantile 4.5: 1, 2 -> group 1; 3, 4 -> group 2; 5, 6 -> group 3, in the series' own order.
    EXPECT_EQ(coarse_grain_quantile({6, 1, 4, 3, 2, 5}, 3), (std::vector<int>{3, 1, 2, 2, 1, 3}));
    // Two groups of 1..4: the median is 2.5.
    EXPECT_EQ(coarse_grain_quantile({4, 3, 2, 1}, 2), (std::vector<int>{2, 2, 1, 1}));
    // The minimum belongs to the first group, ties stay together.
    EXPECT_EQ(coarse_grain_quantile({0, 0, 0, 5, 5, 5}, 2), (std::vector<int>{1, 1, 1, 2, 2, 2}));
}

TEST(Catch22Stats, LinearFitRecoversAnExactLine) {
    double slope = 0, intercept = 0;
    linear_fit({0, 1, 2, 3, 4}, {1, 3, 5, 7, 9}, slope, intercept);
    EXPECT_NEAR(slope, 2.0, 1e-14);
    EXPECT_NEAR(intercept, 1.0, 1e-14);
    // Least squares through (0, 0), (1, 1), (2, 0): slope 0, intercept 1/3.
    linear_fit({0, 1, 2}, {0, 1, 0}, slope, intercept);
    EXPECT_NEAR(slope, 0.0, 1e-15);
    EXPECT_NEAR(intercept, 1.0 / 3.0, 1e-15);
}

TEST(Catch22Stats, ReferenceMeanAndSpread) {
    // DN_Mean and DN_Spread_Std of the reference's catch24 outputs are the mean and sample sd of the raw input;
    // the FFT autocorrelation of each z-scored reference input equals the direct sum.
    std::vector<t2imu::test::Catch22Reference> cases;
    CATCH22_REFERENCE_OR_SKIP(cases);
    int checked = 0;
    for (const auto& c : cases) {
        if (!c.expected.count("DN_Mean")) continue;
        const double m = c.expected.at("DN_Mean"), sd = c.expected.at("DN_Spread_Std");
        EXPECT_TRUE(t2imu::test::catch22_close(mean(c.raw), m)) << c.name << ": " << mean(c.raw) << " vs " << m;
        EXPECT_TRUE(t2imu::test::catch22_close(sample_std(c.raw), sd))
            << c.name << ": " << sample_std(c.raw) << " vs " << sd;
        const Series fast = autocorrelation(c.z);
        for (size_t k = 0; k < fast.size(); ++k) ASSERT_NEAR(fast[k], c.acf[k], 1e-10) << c.name << " lag " << k;
        ++checked;
    }
    EXPECT_GE(checked, 20);
}
