// core/error: the one-line message "FILE: FIELD: expected EXPECTED (got GOT)", with what it quotes from an input
// made printable (control bytes and bidi controls escaped) and cut, so a hostile input cannot fill a terminal,
// rewrite it with escape sequences or reorder what the line says.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"

using namespace t2imu;

TEST(Error, TheMessageIsOneLineNamingFileFieldExpectedAndGot) {
    EXPECT_STREQ(Error("f.csv", "line 3", "a number", "nan").what(), "f.csv: line 3: expected a number (got nan)");
    EXPECT_STREQ(Error("", "", "a thing").what(), "expected a thing");
}

TEST(Error, ControlBytesAndBidiControlsAreEscaped) {
    const std::string got = std::string("a\nb\x1b[2Jc\x7f") + "\xe2\x80\xae" + "txt.exe" + "\xe2\x81\xa6";
    const std::string m = Error("p.tsv", "line 1", "a prompt", got).what();
    EXPECT_EQ(m, "p.tsv: line 1: expected a prompt (got a\\x0Ab\\x1B[2Jc\\x7F\\u202Etxt.exe\\u2066)");
    EXPECT_EQ(printable_text("caf\xc3\xa9 \xe2\x80\x8f", 100), "caf\xc3\xa9 \\u200F");  // other UTF-8 is kept
    EXPECT_EQ(std::string(Error("x\ty").what()), "x\\x09y");
}

TEST(Error, HugeQuotesAreCutAfterTheirHead) {
    const std::string digits(301, '9'), text(10000, 'x');
    const std::string m = Error("--seconds", "seconds", "at most 9.8", digits + ".000000").what();
    EXPECT_EQ(m, "--seconds: seconds: expected at most 9.8 (got 999999999999...(301 digits).000000)");
    EXPECT_EQ(printable_text("(3, 123456789012345678901234)", 100),
              "(3, 123456789012345678901234)");  // 24 digits: kept
    EXPECT_EQ(printable_text("(3, 1234567890123456789012345)", 100), "(3, 123456789012...(25 digits))");
    const std::string long_path = "/data/" + std::string(300, 'p') + "/file.csv: line 2: expected a number";
    EXPECT_EQ(std::string(Error("in", "recordings", "a usable one", long_path).what()),
              "in: recordings: expected a usable one (got " + long_path + ")");
    EXPECT_NE(std::string(Error("x", "y", "z", text).what()).find("... (10000 bytes))"), std::string::npos);
    EXPECT_LE(std::string(Error(text).what()).size(), 2030u);
    // A cut never splits a UTF-8 character: "é" (2 bytes) repeated, cut at an odd count of bytes.
    std::string accents;
    for (int i = 0; i < 100; ++i) accents += "\xc3\xa9";
    const std::string cut = printable_text(accents, 5);
    EXPECT_EQ(cut, "\xc3\xa9\xc3\xa9\xc3\xa9... (200 bytes)");
}
