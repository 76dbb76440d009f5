// core/parse: the one strict text-to-number conversion, the list splitter and the suffix check.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "core/parse.hpp"
#include "test_util.hpp"

using namespace t2imu;

TEST(Parse, NumbersAreTheWholeText) {
    EXPECT_EQ(parse_number("1.5"), 1.5);
    EXPECT_EQ(parse_number("-2e-3"), -2e-3);
    EXPECT_TRUE(std::isnan(*parse_number("nan")));
    EXPECT_TRUE(std::isinf(*parse_number("inf")));
    for (const char* bad : {"", "1.5x", "x1", "1 2", "1,5", " ", "--1"}) EXPECT_FALSE(parse_number(bad)) << bad;
    EXPECT_EQ(parse_finite("3"), 3.0);
    for (const char* bad : {"nan", "inf", "-inf", "1e400", ""}) EXPECT_FALSE(parse_finite(bad)) << bad;
}

TEST(Parse, IntegersAreDecimalDigitsWithinLongLong) {
    EXPECT_EQ(parse_integer("42"), 42);
    EXPECT_EQ(parse_integer("-7"), -7);
    EXPECT_EQ(parse_integer("9223372036854775807"), 9223372036854775807LL);
    for (const char* bad : {"", "+1", " 1", "1.0", "1e3", "0x10", "9223372036854775808", "12a"}) EXPECT_FALSE(parse_integer(bad)) << bad;
}

TEST(Parse, ThrowingFormsNameTheSourceAndField) {
    EXPECT_EQ(finite_number("0.25", "f.csv", "line 3"), 0.25);
    EXPECT_EQ(test::error_message([] { finite_number("nan", "f.csv", "line 3"); }), "f.csv: line 3: expected a number (got 'nan')");
    EXPECT_EQ(integer_in("17", 0, 99, "env", "RANK"), 17);
    EXPECT_EQ(test::error_message([] { integer_in("100", 0, 99, "env", "RANK"); }), "env: RANK: expected a whole number from 0 to 99 (got '100')");
}

TEST(Parse, ListsDropEmptyItemsAndSuffixesAreChecked) {
    EXPECT_EQ(split_list("a,b,,c,"), (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_TRUE(split_list("").empty());
    EXPECT_EQ(split_list("x;y", ';'), (std::vector<std::string>{"x", "y"}));
    EXPECT_TRUE(ends_with("preset.toml", ".toml"));
    EXPECT_FALSE(ends_with("toml", ".toml"));
    EXPECT_TRUE(ends_with("a_joints.npy", "_joints.npy"));
}
