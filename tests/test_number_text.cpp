// core/number_text: numbers as text through std::to_chars, for any double without reading past a buffer.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdlib>

#include "core/number_text.hpp"

using namespace t2imu;

TEST(NumberText, FixedDropsTrailingZerosAndNegativeZero) {
    EXPECT_EQ(fixed_text(0, 6), "0");
    EXPECT_EQ(fixed_text(0.05, 6), "0.05");
    EXPECT_EQ(fixed_text(-9.80665, 4), "-9.8066");  // rounded to nearest even on the binary value: -9.806649999...
    EXPECT_EQ(fixed_text(-1e-9, 6), "0");
    EXPECT_EQ(fixed_text(-0.0, 3), "0");
    EXPECT_EQ(fixed_text(2.5, 0), "2");  // round half to even, as printf's %.0f
    EXPECT_EQ(fixed_text(123456.0, 2), "123456");
    std::string out = "x=";
    append_fixed(out, 1.25, 1);
    EXPECT_EQ(out, "x=1.2");
}

TEST(NumberText, AnyDoubleIsWrittenInFullAndReadsBack) {
    // 1e43 and more once overran snprintf-sized buffers: every digit is now there, and nothing else.
    for (const double v : {1e43, -1e300, DBL_MAX, -DBL_MAX, 4.9e-324, 123456789.123456789}) {
        const std::string s = fixed_text(v, 17);
        EXPECT_EQ(s.find_first_not_of("-0123456789."), std::string::npos) << s;
        EXPECT_DOUBLE_EQ(std::strtod(s.c_str(), nullptr), std::fabs(v) < 1e-17 ? 0.0 : v) << s;
    }
    EXPECT_EQ(fixed_text(DBL_MAX, 17).size(), 309u);  // 309 digits, no point once the zeros are dropped
    EXPECT_EQ(fixed_text(NAN, 3), "nan");
    EXPECT_EQ(fixed_text(-INFINITY, 3), "-inf");
}

TEST(NumberText, GeneralIsPrintfsPercentG) {
    EXPECT_EQ(general_text(0.1, 6), "0.1");
    EXPECT_EQ(general_text(1e20, 6), "1e+20");
    EXPECT_EQ(general_text(-2.5e-7, 6), "-2.5e-07");
    EXPECT_EQ(general_text(1234567, 6), "1.23457e+06");
    EXPECT_EQ(general_text(100, 6), "100");
    EXPECT_EQ(general_text(DBL_MAX, 17), "1.7976931348623157e+308");
    EXPECT_EQ(general_text(1.0 / 3.0, 40), "0.33333333333333331");  // at most 17 digits
}
