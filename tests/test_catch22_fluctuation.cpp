// catch22_fluctuation.cpp: SC_FluctAnal_2_rsrangefit_50_1_logi_prop_r1 and SC_FluctAnal_2_dfa_50_1_2_logi_prop_r1:
// the window-size grid (too few sizes give 0), the share of sizes in the first of the two fitted lines, and the
// reference outputs.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analysis/catch22_features.hpp"
#include "catch22_reference.hpp"

using namespace t2imu::catch22_detail;
using t2imu::test::Catch22Reference;

namespace {
Series noise(size_t n, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> g;
    Series x(n);
    for (double& v : x) v = g(rng);
    return x;
}
}  // namespace

TEST(Catch22Fluctuation, TooFewWindowSizesGiveZero) {
    // Window sizes run from 5 to n / 2: n = 30 gives the 11 sizes 5..15, fewer than two lines of 6 points each.
    EXPECT_DOUBLE_EQ(fluct_anal_rsrangefit_prop_r1(noise(30, 1)), 0.0);
    EXPECT_DOUBLE_EQ(fluct_anal_dfa_prop_r1(noise(30, 1)), 0.0);
}

TEST(Catch22Fluctuation, OutputIsAShareOfTheWindowSizes) {
    // n = 32: the 12 sizes 5..16, exactly two lines of 6 points: the split can only be at 6, so 6 / 12.
    EXPECT_DOUBLE_EQ(fluct_anal_rsrangefit_prop_r1(noise(32, 2)), 0.5);
    EXPECT_DOUBLE_EQ(fluct_anal_dfa_prop_r1(noise(32, 2)), 0.5);
    // n = 40: the 16 sizes 5..20 (every integer: the log grid is finer than their spacing): splits 6..10 of 16.
    for (unsigned seed = 0; seed < 5; ++seed)
        for (double v : {fluct_anal_rsrangefit_prop_r1(noise(40, seed)), fluct_anal_dfa_prop_r1(noise(40, seed))}) {
            EXPECT_NEAR(std::remainder(v * 16, 1.0), 0.0, 1e-12) << v;
            EXPECT_GE(v, 6.0 / 16);
            EXPECT_LE(v, 10.0 / 16);
        }
}

TEST(Catch22Fluctuation, MatchesTheReference) {
    std::vector<Catch22Reference> cases;
    CATCH22_REFERENCE_OR_SKIP(cases);
    using t2imu::test::expect_catch22_feature;
    EXPECT_GE(expect_catch22_feature(cases, "SC_FluctAnal_2_rsrangefit_50_1_logi_prop_r1",
                                     [](const Catch22Reference& c) { return fluct_anal_rsrangefit_prop_r1(c.z); }),
              25);
    EXPECT_GE(expect_catch22_feature(cases, "SC_FluctAnal_2_dfa_50_1_2_logi_prop_r1",
                                     [](const Catch22Reference& c) { return fluct_anal_dfa_prop_r1(c.z); }),
              25);
}
