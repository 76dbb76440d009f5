// catch22_forecast.cpp: FC_LocalSimple_mean3_stderr and FC_LocalSimple_mean1_tauresrat on hand-computed series
// and against the reference outputs.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/catch22_features.hpp"
#include "catch22_reference.hpp"

using namespace t2imu::catch22_detail;
using t2imu::test::Catch22Reference;

TEST(Catch22Forecast, Mean3StderrOfHandComputedResiduals) {
    // A ramp is forecast by the mean of its last three values with a constant error of 2: sd 0.
    EXPECT_NEAR(local_mean3_stderr({0, 1, 2, 3, 4, 5, 6, 7}), 0.0, 1e-15);
    // 0 0 0 3 0 0 0: residuals 3 - 0, 0 - 1, 0 - 1, 0 - 1 = 3, -1, -1, -1: mean 0, squares 12, sd sqrt(12 / 3) = 2.
    EXPECT_NEAR(local_mean3_stderr({0, 0, 0, 3, 0, 0, 0}), 2.0, 1e-15);
}

TEST(Catch22Forecast, Mean1TauresratIsTheRatioOfFirstZeroCrossings) {
    // A sine of period 40 (n = 400): its autocorrelation first reaches zero near lag 10. The increments are
    // the same sine shifted by a quarter period, whose first zero is also near 10: ratio near 1, and exactly
    // the ratio of the two directly summed crossings.
    Series x;
    for (int t = 0; t < 400; ++t) x.push_back(std::sin(2 * M_PI * t / 40.0));
    Series diff;
    for (size_t t = 1; t < x.size(); ++t) diff.push_back(x[t] - x[t - 1]);
    const Series acf = t2imu::test::direct_autocorrelation(x);
    auto first_zero = [](const Series& r) {
        size_t k = 1;
        while (k < r.size() && r[k] > 0) ++k;
        return static_cast<double>(k);
    };
    const double expected = first_zero(t2imu::test::direct_autocorrelation(diff)) / first_zero(acf);
    EXPECT_DOUBLE_EQ(local_mean1_tauresrat(x, acf), expected);
    EXPECT_NEAR(expected, 1.0, 0.11);
    // Alternating signs: the increments alternate too; both autocorrelations are negative at lag 1: 1 / 1.
    EXPECT_DOUBLE_EQ(local_mean1_tauresrat({1, -1, 1, -1, 1, -1, 1, -1}, {1, -0.875, 0.75}), 1.0);
}

TEST(Catch22Forecast, MatchesTheReference) {
    std::vector<Catch22Reference> cases;
    CATCH22_REFERENCE_OR_SKIP(cases);
    using t2imu::test::expect_catch22_feature;
    EXPECT_GE(expect_catch22_feature(cases, "FC_LocalSimple_mean3_stderr",
                                     [](const Catch22Reference& c) { return local_mean3_stderr(c.z); }),
              25);
    EXPECT_GE(expect_catch22_feature(cases, "FC_LocalSimple_mean1_tauresrat",
                                     [](const Catch22Reference& c) { return local_mean1_tauresrat(c.z, c.acf); }),
              25);
}
