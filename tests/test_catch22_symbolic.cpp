// catch22_symbolic.cpp: MD_hrv_classic_pnn40, SB_BinaryStats_mean_longstretch1, SB_BinaryStats_diff_longstretch0,
// SB_MotifThree_quantile_hh and SB_TransitionMatrix_3ac_sumdiagcov on hand-computed series and against the
// reference outputs.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/catch22_features.hpp"
#include "catch22_reference.hpp"

using namespace t2imu::catch22_detail;
using t2imu::test::Catch22Reference;

TEST(Catch22Symbolic, Pnn40CountsIncrementsAbove40Milliseconds) {
    // Increments 0.05 (yes), 0.01 (no), -0.06 (yes), 0.041 (yes), 0.035 (no): 3 of 5.
    EXPECT_DOUBLE_EQ(pnn40({0, 0.05, 0.06, 0.0, 0.041, 0.076}), 0.6);
    EXPECT_DOUBLE_EQ(pnn40({0, 0.01, 0.02, 0.03}), 0.0);
}

TEST(Catch22Symbolic, LongestStretchAboveTheMean) {
    // The reference's convention (catch22_symbolic.cpp): an interior run of L samples counts L + 1.
    // 0 1 1 1 0 0 0 0 (mean 3/8): the run of three 1s is interior: 4.
    EXPECT_DOUBLE_EQ(binary_mean_longstretch1({0, 1, 1, 1, 0, 0, 0, 0}), 4.0);
    // The scan stops at n - 2, so a run at the end loses its last sample and counts its length within the
    // scan: 0 0 0 0 0 1 1 1 -> indices 5, 6 scanned -> 2.
    EXPECT_DOUBLE_EQ(binary_mean_longstretch1({0, 0, 0, 0, 0, 1, 1, 1}), 2.0);
}

TEST(Catch22Symbolic, LongestStretchOfDecreases) {
    // Increments +1, -1, -1, -1, +1 x 5: an interior run of three decreases: 4.
    EXPECT_DOUBLE_EQ(binary_diff_longstretch0({0, 1, 0, -1, -2, -1, 0, 1, 2, 3}), 4.0);
    // Three decreases at the start: a run touching the start of the scan counts its length, 3.
    EXPECT_DOUBLE_EQ(binary_diff_longstretch0({5, 4, 3, 2, 3, 4, 5, 6, 7, 8}), 3.0);
}

TEST(Catch22Symbolic, MotifEntropyOfACycleOfThreeSymbols) {
    // 1 2 3 1 2 3 1 2 3 1: the quantiles split it into its three values; the nine words 12, 23, 31 occur three
    // times each: entropy log 3.
    EXPECT_NEAR(motif_three_quantile_hh({1, 2, 3, 1, 2, 3, 1, 2, 3, 1}), std::log(3.0), 1e-14);
    // 1 1 1 2 2 2 3 3 3: the eight words are 11 x2, 12, 22 x2, 23, 33 x2: three of probability 2/8, two of 1/8.
    const double p2 = 2.0 / 8, p1 = 1.0 / 8;
    EXPECT_NEAR(motif_three_quantile_hh({1, 1, 1, 2, 2, 2, 3, 3, 3}), -3 * p2 * std::log(p2) - 2 * p1 * std::log(p1),
                1e-14);
}

TEST(Catch22Symbolic, TransitionMatrixColumnVariances) {
    // First zero of the autocorrelation at lag 1: no downsampling. The cycle 1 2 3 (n = 10) has transitions
    // 1->2, 2->3, 3->1, three each of nine: each column of the probability matrix holds one 1/3 and two 0s,
    // whose sample variance is ((2/9)^2 + 2 (1/9)^2) / 2 = 1/27; three columns: 1/9.
    const Series cycle = {1, 2, 3, 1, 2, 3, 1, 2, 3, 1};
    EXPECT_NEAR(transition_matrix_3ac_sumdiagcov(cycle, {1, -0.5}), 1.0 / 9.0, 1e-15);
    // First zero at lag 2: every other sample, 1 3 2 1 3: transitions 1->3, 3->2, 2->1, 1->3 of four:
    // columns (0, 1/4, 0), (0, 0, 1/4), (2/4, 0, 0): variances 1/48, 1/48, 1/12 -> 1/8.
    EXPECT_NEAR(transition_matrix_3ac_sumdiagcov(cycle, {1, 0.5, -0.5}), 1.0 / 8.0, 1e-15);
}

TEST(Catch22Symbolic, MatchesTheReference) {
    std::vector<Catch22Reference> cases;
    CATCH22_REFERENCE_OR_SKIP(cases);
    using t2imu::test::expect_catch22_feature;
    EXPECT_GE(
        expect_catch22_feature(cases, "MD_hrv_classic_pnn40", [](const Catch22Reference& c) { return pnn40(c.z); }),
        25);
    EXPECT_GE(expect_catch22_feature(cases, "SB_BinaryStats_mean_longstretch1",
                                     [](const Catch22Reference& c) { return binary_mean_longstretch1(c.z); }),
              25);
    EXPECT_GE(expect_catch22_feature(cases, "SB_BinaryStats_diff_longstretch0",
                                     [](const Catch22Reference& c) { return binary_diff_longstretch0(c.z); }),
              25);
    EXPECT_GE(expect_catch22_feature(cases, "SB_MotifThree_quantile_hh",
                                     [](const Catch22Reference& c) { return motif_three_quantile_hh(c.z); }),
              25);
    EXPECT_GE(
        expect_catch22_feature(cases, "SB_TransitionMatrix_3ac_sumdiagcov",
                               [](const Catch22Reference& c) { return transition_matrix_3ac_sumdiagcov(c.z, c.acf); }),
        25);
}
