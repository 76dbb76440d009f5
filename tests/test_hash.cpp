// core/hash: the stable hashes against their published values, and derived_seed pinned to the values every
// recorded synthesis drew from (computed independently from the formula in hash.hpp).
#include <gtest/gtest.h>

#include "core/hash.hpp"

using namespace t2imu;

TEST(Hash, Fnv1a64AndSplitMix64MatchTheirReferenceValues) {
    EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
    EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
    // SplitMix64 seeded with 0: its first two outputs.
    EXPECT_EQ(splitmix64(0x9E3779B97F4A7C15ull), 0xe220a8397b1dcdafull);
    EXPECT_EQ(splitmix64(2 * 0x9E3779B97F4A7C15ull), 0x6e789e6aa1b965f4ull);
    EXPECT_EQ(murmur3_fmix64(0), 0u);
    EXPECT_EQ(murmur3_fmix64(1), 0xb456bcfc34c2cb2cull);
}

TEST(Hash, DerivedSeedsArePinnedAndSeparateTheNames) {
    EXPECT_EQ(derived_seed(7, {"male_average", "waist", "noise"}), 0x846d4fb212492b98ull);
    EXPECT_EQ(derived_seed(7, {"male_averag", "ewaist", "noise"}), 0xb1f1de311f7a6560ull);  // the 0xff separator
    EXPECT_NE(derived_seed(7, {"male_average", "waist", "noise"}), derived_seed(8, {"male_average", "waist", "noise"}));
}
