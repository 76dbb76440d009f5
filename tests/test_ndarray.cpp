#include <gtest/gtest.h>

#include <cmath>

#include "core/ndarray.hpp"

using namespace t2imu;

TEST(NdArray, HalfPrecisionConversions) {
    EXPECT_EQ(half_to_float(0x3c00), 1.0f);
    EXPECT_EQ(half_to_float(0xc000), -2.0f);
    EXPECT_EQ(half_to_float(0x7bff), 65504.0f);               // largest finite half
    EXPECT_EQ(half_to_float(0x0001), std::ldexp(1.0f, -24));  // smallest subnormal
    EXPECT_TRUE(std::isinf(half_to_float(0x7c00)));
    EXPECT_TRUE(std::isnan(half_to_float(0x7e00)));
    for (uint32_t h = 0; h < 0x7c00; ++h) EXPECT_EQ(float_to_half(half_to_float(static_cast<uint16_t>(h))), h) << h;
    // Ties round to even: 1 + 2^-11 lies halfway between 1 and the next half (1 + 2^-10).
    EXPECT_EQ(float_to_half(1.0f + std::ldexp(1.0f, -11)), 0x3c00);
    EXPECT_EQ(float_to_half(1.0f + 3 * std::ldexp(1.0f, -11)), 0x3c02);
    EXPECT_EQ(float_to_half(70000.0f), 0x7c00);
    EXPECT_EQ(float_to_half(-0.0f), 0x8000);
}

TEST(NdArray, BFloat16Conversions) {
    EXPECT_EQ(bfloat16_to_float(0x3f80), 1.0f);
    EXPECT_EQ(float_to_bfloat16(1.0f), 0x3f80);
    EXPECT_EQ(float_to_bfloat16(1.0f + std::ldexp(1.0f, -8)), 0x3f80);      // tie to even
    EXPECT_EQ(float_to_bfloat16(1.0f + 3 * std::ldexp(1.0f, -8)), 0x3f82);  // tie to even, upwards
    EXPECT_TRUE(std::isnan(bfloat16_to_float(float_to_bfloat16(NAN))));
}

TEST(NdArray, ConvertsBetweenElementTypes) {
    const NdArray a = NdArray::from(std::vector<int32_t>{-3, 0, 7}, {3});
    EXPECT_EQ(a.to<double>(), (std::vector<double>{-3, 0, 7}));
    EXPECT_EQ(a.shape_str(), "(3,)");
    EXPECT_THROW(NdArray::from(std::vector<float>{1, 2}, {3}), Error);
}
