// catch22_autocorrelation.cpp: CO_f1ecac, CO_FirstMin_ac, CO_HistogramAMI_even_2_5, CO_trev_1_num,
// IN_AutoMutualInfoStats_40_gaussian_fmmi and CO_Embed2_Dist_tau_d_expfit_meandiff on hand-computed series and
// against the reference outputs.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/catch22_features.hpp"
#include "catch22_reference.hpp"

using namespace t2imu::catch22_detail;
using t2imu::test::Catch22Reference;

TEST(Catch22Autocorrelation, FirstOneOverECrossingIsInterpolated) {
    // 1/e = 0.3679 is crossed between lags 1 (0.5) and 2 (0.2): 1 + (0.5 - 1/e) / (0.5 - 0.2).
    EXPECT_NEAR(first_1_e_crossing({1, 0.5, 0.2, 0.1}), 1 + (0.5 - std::exp(-1.0)) / 0.3, 1e-15);
    // An exponential decay exp(-k / 2.5) crosses between lags 2 and 3.
    Series acf;
    for (int k = 0; k < 10; ++k) acf.push_back(std::exp(-k / 2.5));
    EXPECT_NEAR(first_1_e_crossing(acf), 2 + (acf[2] - std::exp(-1.0)) / (acf[2] - acf[3]), 1e-14);
    EXPECT_DOUBLE_EQ(first_1_e_crossing({1, 0.9, 0.8, 0.7}), 4.0);  // never: n
}

TEST(Catch22Autocorrelation, FirstMinimumIsTheFirstStrictLocalMinimum) {
    EXPECT_DOUBLE_EQ(first_minimum({1, 0.5, 0.2, 0.3, 0.1, 0.4}), 2.0);
    EXPECT_DOUBLE_EQ(first_minimum({1, 0.5, 0.5, 0.6}), 4.0);  // a flat bottom is not strict: none, n
}

TEST(Catch22Autocorrelation, HistogramAmiOfDeterminedAndIndependentLags) {
    // Alternating -1, 1: x_{t+2} = x_t, two equally likely bins: AMI = log 2.
    Series alternating;
    for (int t = 0; t < 10; ++t) alternating.push_back(t % 2 ? 1.0 : -1.0);
    EXPECT_NEAR(histogram_ami_even(alternating, 2, 5), std::log(2.0), 1e-14);
    // Pattern a a a a b b b b: over whole cycles the pairs (x_t, x_{t+2}) are aa, aa, ab, ab, bb, bb, ba, ba,
    // each a quarter: the joint distribution is the product of its marginals, AMI = 0.
    Series independent;
    for (int t = 0; t < 66; ++t) independent.push_back((t % 8) < 4 ? 0.0 : 1.0);
    EXPECT_NEAR(histogram_ami_even(independent, 2, 5), 0.0, 1e-14);
}

TEST(Catch22Autocorrelation, TimeReversibilityIsTheMeanCubedIncrement) {
    // Increments 1, 2: (1 + 8) / 2.
    EXPECT_DOUBLE_EQ(time_reversibility({0, 1, 3}), 4.5);
    // Reversing the series negates it.
    EXPECT_DOUBLE_EQ(time_reversibility({3, 1, 0}), -4.5);
}

TEST(Catch22Autocorrelation, GaussianAmiFirstMinimumOfAPeriodicSeries) {
    // A sine of period 8 sampled with a phase offset (so no lag correlation is exactly +-1): the Pearson
    // correlation at lag k is about cos(2 pi k / 8), the Gaussian AMI -log(1 - r^2) / 2 is smallest where
    // r = 0, at lags 2, 6, ...: the output is that lag's 0-based index among lags 1..40, i.e. 1.
    Series x;
    for (int t = 0; t < 200; ++t) x.push_back(std::sin(2 * M_PI * t / 8.0 + 0.3) + 0.3 * std::sin(2 * M_PI * t / 61.0));
    EXPECT_DOUBLE_EQ(gaussian_ami_first_minimum(x, 40), 1.0);
}

TEST(Catch22Autocorrelation, MatchesTheReference) {
    std::vector<Catch22Reference> cases;
    CATCH22_REFERENCE_OR_SKIP(cases);
    using t2imu::test::expect_catch22_feature;
    EXPECT_GE(
        expect_catch22_feature(cases, "CO_f1ecac", [](const Catch22Reference& c) { return first_1_e_crossing(c.acf); }),
        25);
    EXPECT_GE(
        expect_catch22_feature(cases, "CO_FirstMin_ac", [](const Catch22Reference& c) { return first_minimum(c.acf); }),
        25);
    EXPECT_GE(expect_catch22_feature(cases, "CO_HistogramAMI_even_2_5",
                                     [](const Catch22Reference& c) { return histogram_ami_even(c.z, 2, 5); }),
              25);
    EXPECT_GE(expect_catch22_feature(cases, "CO_trev_1_num",
                                     [](const Catch22Reference& c) { return time_reversibility(c.z); }),
              25);
    EXPECT_GE(expect_catch22_feature(cases, "IN_AutoMutualInfoStats_40_gaussian_fmmi",
                                     [](const Catch22Reference& c) { return gaussian_ami_first_minimum(c.z, 40); }),
              25);
    EXPECT_GE(expect_catch22_feature(cases, "CO_Embed2_Dist_tau_d_expfit_meandiff",
                                     [](const Catch22Reference& c) { return embed2_dist_expfit_meandiff(c.z, c.acf); }),
              25);
}
