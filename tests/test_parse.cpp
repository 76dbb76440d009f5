// core/parse: the one strict text-to-number conversion, the list splitter and the suffix check.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <utility>

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
    for (const char* bad : {"", "+1", " 1", "1.0", "1e3", "0x10", "9223372036854775808", "12a"})
        EXPECT_FALSE(parse_integer(bad)) << bad;
}

TEST(Parse, ThrowingFormsNameTheSourceAndField) {
    EXPECT_EQ(finite_number("0.25", "f.csv", "line 3"), 0.25);
    EXPECT_EQ(test::error_message([] { finite_number("nan", "f.csv", "line 3"); }),
              "f.csv: line 3: expected a number (got 'nan')");
    EXPECT_EQ(integer_in("17", 0, 99, "env", "RANK"), 17);
    EXPECT_EQ(test::error_message([] { integer_in("100", 0, 99, "env", "RANK"); }),
              "env: RANK: expected a whole number from 0 to 99 (got '100')");
}

TEST(Parse, ListsDropEmptyItemsAndSuffixesAreChecked) {
    EXPECT_EQ(split_list("a,b,,c,"), (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_TRUE(split_list("").empty());
    EXPECT_EQ(split_list("x;y", ';'), (std::vector<std::string>{"x", "y"}));
    EXPECT_TRUE(ends_with("preset.toml", ".toml"));
    EXPECT_FALSE(ends_with("toml", ".toml"));
    EXPECT_TRUE(ends_with("a_joints.npy", "_joints.npy"));
}

TEST(Parse, NamedOverridesSplitOnceForEveryPresetOption) {
    const NamedOverrides o = parse_named_overrides("sisfall,bits=12,acc_range_g=8,", "--sensor");
    EXPECT_EQ(o.name, "sisfall");
    ASSERT_EQ(o.overrides.size(), 2u);  // the trailing comma adds nothing
    EXPECT_EQ(o.overrides[1], (std::pair<std::string, std::string>{"acc_range_g", "8"}));
    EXPECT_EQ(parse_named_overrides("none", "--sensor").overrides.size(), 0u);
    EXPECT_EQ(parse_named_overrides("8,seed=", "--body").overrides[0].second, "");  // the value's parser refuses it
    EXPECT_EQ(test::error_message([] { parse_named_overrides("smartphone,bits", "--sensor"); }),
              "--sensor: bits: expected key=value");
    EXPECT_THROW(parse_named_overrides("smartphone,,bits=3", "--sensor"), Error);
}

TEST(Parse, ShardsAreTwoWholeNumbersWithOneToN) {
    EXPECT_EQ(parse_shard("2/5", "--shard", "shard"), (std::pair<int, int>{2, 5}));
    EXPECT_EQ(parse_shard("1/1", "--shard", "shard"), (std::pair<int, int>{1, 1}));
    for (const char* bad : {"0/3", "4/3", "1/0", "1/", "/3", "1/3x", "1 /3", "1/3/4", "+1/3", "1.0/3", "", "3"})
        EXPECT_THROW(parse_shard(bad, "--shard", "shard"), Error) << bad;
    EXPECT_EQ(test::error_message([] { parse_shard("4/3", "--shard", "shard"); }),
              "--shard: shard: expected I/N with 1 <= I <= N (got 4/3)");
}

// Numbers from text are read in core/parse alone (the strict forms above): no other file of src/ converts text with
// the standard library's lenient readers, which accept "1.5x" or stop at the first bad character.
TEST(Parse, NoSourceOutsideCoreReadsNumbersOnItsOwn) {
    const std::regex stray(R"(std::(stod|stoi|stol|stoll|stof|strtod|strtol|from_chars)\b|\bsscanf\b)");
    int files = 0;
    for (const auto& e : std::filesystem::recursive_directory_iterator(std::string(T2IMU_SOURCE_DIR) + "/src")) {
        const std::string path = e.path().generic_string();
        if (!e.is_regular_file() || path.find("/src/core/") != std::string::npos) continue;
        std::ifstream in(e.path());
        std::string line;
        for (int n = 1; std::getline(in, line); ++n)
            EXPECT_FALSE(std::regex_search(line, stray)) << path << ":" << n << ": " << line;
        ++files;
    }
    EXPECT_GT(files, 100);
}
