// catch22_distribution.cpp: DN_HistogramMode_5/_10 and DN_OutlierInclude_p/n_001_mdrmd on hand-computed series
// and against the reference outputs.
#include <gtest/gtest.h>

#include "analysis/catch22_features.hpp"
#include "catch22_reference.hpp"

using namespace t2imu::catch22_detail;
using t2imu::test::Catch22Reference;

TEST(Catch22Distribution, HistogramModeIsTheFullestBinsCentre) {
    // [0, 5] in 5 bins of width 1: counts 3, 1, 1, 1, 2 (the maximum 5 falls in the last bin): centre 0.5.
    EXPECT_DOUBLE_EQ(histogram_mode({0, 0.1, 0.2, 1.5, 2.5, 3.5, 4.5, 5}, 5), 0.5);
    // Ten bins of width 0.5: 4.5 and 5 both land in the last bin [4.5, 5], the fullest (2): centre 4.75.
    EXPECT_DOUBLE_EQ(histogram_mode({0, 1.2, 2.2, 3.2, 4.5, 5}, 10), 4.75);
}

TEST(Catch22Distribution, HistogramModeAveragesTiedBins) {
    // Bins 0 and 4 hold two values each: the mean of their centres 0.5 and 4.5.
    EXPECT_DOUBLE_EQ(histogram_mode({0, 0, 2.5, 4.9, 5}, 5), 2.5);
}

TEST(Catch22Distribution, OutlierTimingOfLateAndEarlyEvents) {
    // n = 10. The positive values (0.02) sit at times 6..10 at every threshold 0, 0.01, 0.02: median time 8,
    // position 8 / 5 - 1 = 0.6. The negated series' positive values sit at times 1..5: 3 / 5 - 1 = -0.4.
    // Neither is trimmed: 4 intervals among 5 samples on that side are 80 % > 2 %.
    const Series x = {-1, -1, -1, -1, -1, 0.02, 0.02, 0.02, 0.02, 0.02};
    EXPECT_NEAR(outlier_include_mdrmd(x, true), 0.6, 1e-15);
    EXPECT_NEAR(outlier_include_mdrmd(x, false), -0.4, 1e-15);
}

TEST(Catch22Distribution, OutlierTimingMedianOverThresholds) {
    // n = 4, x = 0, 0, 0, 0.01 -> thresholds 0 and 0.01. At 0 every sample is an event: median time 2.5,
    // position 2.5 / 2 - 1 = 0.25; at 0.01 only time 4: 4 / 2 - 1 = 1. Intervals: 3 of 4 (75 %) and 0 of 4
    // (trimmed from the top), so the output is the median of {0.25}.
    EXPECT_NEAR(outlier_include_mdrmd({0, 0, 0, 0.01}, true), 0.25, 1e-15);
}

TEST(Catch22Distribution, MatchesTheReference) {
    std::vector<Catch22Reference> cases;
    CATCH22_REFERENCE_OR_SKIP(cases);
    using t2imu::test::expect_catch22_feature;
    EXPECT_GE(expect_catch22_feature(cases, "DN_HistogramMode_5",
                                     [](const Catch22Reference& c) { return histogram_mode(c.z, 5); }),
              25);
    EXPECT_GE(expect_catch22_feature(cases, "DN_HistogramMode_10",
                                     [](const Catch22Reference& c) { return histogram_mode(c.z, 10); }),
              25);
    EXPECT_GE(expect_catch22_feature(cases, "DN_OutlierInclude_p_001_mdrmd",
                                     [](const Catch22Reference& c) { return outlier_include_mdrmd(c.z, true); }),
              25);
    EXPECT_GE(expect_catch22_feature(cases, "DN_OutlierInclude_n_001_mdrmd",
                                     [](const Catch22Reference& c) { return outlier_include_mdrmd(c.z, false); }),
              25);
}
