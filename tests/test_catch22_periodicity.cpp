// catch22_periodicity.cpp: PD_PeriodicityWang_th0_01 (Wang, Smith & Hyndman's detector) on sines of known period,
// on a series with no period, and against the reference outputs.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/catch22_features.hpp"
#include "catch22_reference.hpp"

using namespace t2imu::catch22_detail;
using t2imu::test::Catch22Reference;

TEST(Catch22Periodicity, FindsTheLagOfASinesPeriod) {
    // The autocovariance of a sine of period P peaks at lag P after a trough at P / 2; the output is that
    // lag's 0-based index among the lags 1, 2, ..., i.e. P - 1. A linear trend is removed by the spline first.
    for (int period : {8, 12, 20}) {
        Series x;
        for (int t = 0; t < 120; ++t) x.push_back(std::sin(2 * M_PI * t / period) + 0.01 * t);
        EXPECT_DOUBLE_EQ(periodicity_wang(x, 0.01), period - 1.0) << "period " << period;
    }
}

TEST(Catch22Periodicity, NoPeriodGivesZero) {
    // A cubic lies in the spline basis: the residual is zero (to rounding), so no peak rises 0.01 above a trough.
    Series cubic;
    for (int t = 0; t < 60; ++t) cubic.push_back(std::pow(t / 10.0, 3) - 2 * t);
    EXPECT_DOUBLE_EQ(periodicity_wang(cubic, 0.01), 0.0);
    // A period longer than the lags searched (up to ceil(n / 3)) has no peak to find.
    Series slow;
    for (int t = 0; t < 60; ++t) slow.push_back(std::sin(2 * M_PI * t / 50.0));
    EXPECT_DOUBLE_EQ(periodicity_wang(slow, 0.01), 0.0);
}

TEST(Catch22Periodicity, MatchesTheReference) {
    std::vector<Catch22Reference> cases;
    CATCH22_REFERENCE_OR_SKIP(cases);
    EXPECT_GE(
        t2imu::test::expect_catch22_feature(cases, "PD_PeriodicityWang_th0_01",
                                            [](const Catch22Reference& c) { return periodicity_wang(c.z, 0.01); }),
        25);
}
