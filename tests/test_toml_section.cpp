// Strict TOML reading: typed reads, absent keys leaving defaults, required keys, arrays of strings, sub-tables
// and arrays of tables with dotted names in messages, unknown keys refused by name, parser errors naming the
// source.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "core/toml_section.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {}  // namespace

TEST(TomlSection, ReadsTypedValuesAndLeavesAbsentOnesAlone) {
    const toml::table doc = parse_toml_text("name = \"walk\"\nsteps = 50\nrate = 20.5\nfilter = true\n", "cfg.toml");
    TomlSection s(doc, "cfg.toml", "");
    std::string name;
    int steps = 0;
    double rate = 0, missing = 7.25;
    bool filter = false;
    s.read("name", name);
    s.read("steps", steps);
    s.read("rate", rate);
    s.read("filter", filter);
    s.read("missing", missing);
    EXPECT_EQ(name, "walk");
    EXPECT_EQ(steps, 50);
    EXPECT_DOUBLE_EQ(rate, 20.5);
    EXPECT_TRUE(filter);
    EXPECT_DOUBLE_EQ(missing, 7.25);  // absent: unchanged
    EXPECT_NO_THROW(s.refuse_unknown_keys());
}

TEST(TomlSection, WrongTypesAreRefusedNamingTheField) {
    const toml::table doc =
        parse_toml_text("[synth]\nsteps = 4.9e47\nname = 3\nflag = \"yes\"\nrate = \"fast\"\n", "cfg.toml");
    TomlSection top(doc, "cfg.toml", "");
    TomlSection synth = top.table("synth");
    int steps = 0;
    std::string name;
    bool flag = false;
    double rate = 0;
    // An integer field takes only a TOML integer (a float out of range must not be converted).
    std::string m = test::error_message([&] { synth.read("steps", steps); });
    EXPECT_TRUE(test::contains(m, "cfg.toml") && test::contains(m, "synth.steps") && test::contains(m, "an integer"))
        << m;
    m = test::error_message([&] { synth.read("name", name); });
    EXPECT_TRUE(test::contains(m, "synth.name") && test::contains(m, "a string")) << m;
    m = test::error_message([&] { synth.read("flag", flag); });
    EXPECT_TRUE(test::contains(m, "synth.flag") && test::contains(m, "true or false")) << m;
    m = test::error_message([&] { synth.read("rate", rate); });
    EXPECT_TRUE(test::contains(m, "synth.rate") && test::contains(m, "a number")) << m;
    EXPECT_EQ(steps, 0);  // nothing assigned on failure
}

TEST(TomlSection, AnUnsignedFieldTakesOnlyAWholeNumberFromZero) {
    const toml::table doc = parse_toml_text("[har]\nseed = 12\nneg = -3\n", "cfg.toml");
    TomlSection top(doc, "cfg.toml", "");
    TomlSection har = top.table("har");
    uint64_t seed = 0, neg = 7, missing = 5;
    har.read("seed", seed);
    har.read("missing", missing);
    EXPECT_EQ(seed, 12u);
    EXPECT_EQ(missing, 5u);  // absent: unchanged
    const std::string m = test::error_message([&] { har.read("neg", neg); });
    EXPECT_EQ(m, "cfg.toml: har.neg: expected a whole number from 0 (got -3)");
    EXPECT_EQ(neg, 7u);  // nothing assigned on failure
    EXPECT_NO_THROW(har.refuse_unknown_keys());
}

TEST(TomlSection, RequiredKeysAndArraysOfStrings) {
    const toml::table doc =
        parse_toml_text("positions = [\"waist\", \"wrist\"]\nmixed = [\"a\", 2]\nnot_array = \"a\"\n", "c.toml");
    TomlSection s(doc, "c.toml", "");
    std::vector<std::string> positions = {"old"}, other;
    s.read("positions", positions);
    EXPECT_EQ(positions, (std::vector<std::string>{"waist", "wrist"}));
    std::string m = test::error_message([&] { s.read("mixed", other); });
    EXPECT_TRUE(test::contains(m, "mixed") && test::contains(m, "an array of strings")) << m;
    m = test::error_message([&] { s.read("not_array", other); });
    EXPECT_TRUE(test::contains(m, "not_array") && test::contains(m, "an array of strings")) << m;
    std::string model;
    m = test::error_message([&] { s.require("model", model); });
    EXPECT_TRUE(test::contains(m, "c.toml") && test::contains(m, "model") && test::contains(m, "required")) << m;
}

TEST(TomlSection, SubTablesAndArraysOfTablesNameTheirPath) {
    const toml::table doc = parse_toml_text(
        "scalar = 5\n"
        "[har]\nepochs = 3\n[har.optimiser]\nlr = 0.001\n"
        "[[sources]]\nname = \"mdm\"\n[[sources]]\nname = \"retrieval\"\ntypo = 1\n",
        "exp.toml");
    TomlSection top(doc, "exp.toml", "");
    TomlSection har = top.table("har");
    int epochs = 0;
    har.read("epochs", epochs);
    EXPECT_EQ(epochs, 3);
    TomlSection opt = har.table("optimiser");
    double lr = 0;
    opt.read("lr", lr);
    EXPECT_DOUBLE_EQ(lr, 0.001);
    // har's own keys are all read: its sub-table counts as read.
    EXPECT_NO_THROW(har.refuse_unknown_keys());
    // An absent table reads as empty: defaults stay.
    TomlSection none = top.table("absent");
    int kept = 9;
    none.read("x", kept);
    EXPECT_EQ(kept, 9);
    EXPECT_NO_THROW(none.refuse_unknown_keys());
    std::vector<TomlSection> sources = top.array_of_tables("sources");
    ASSERT_EQ(sources.size(), 2u);
    std::string name;
    sources[1].read("name", name);
    EXPECT_EQ(name, "retrieval");
    std::string m = test::error_message([&] { sources[1].refuse_unknown_keys(); });
    EXPECT_TRUE(test::contains(m, "exp.toml") && test::contains(m, "sources[1].typo") &&
                test::contains(m, "a known key"))
        << m;
    // A scalar where a table is expected, and where an array of tables is.
    m = test::error_message([&] { top.table("scalar"); });
    EXPECT_TRUE(test::contains(m, "scalar") && test::contains(m, "a table")) << m;
    m = test::error_message([&] { top.array_of_tables("scalar"); });
    EXPECT_TRUE(test::contains(m, "scalar") && test::contains(m, "an array of tables")) << m;
    // Every top-level key has now been named by a read.
    EXPECT_NO_THROW(top.refuse_unknown_keys());
}

TEST(TomlSection, UnknownKeysAreRefusedByName) {
    const toml::table doc = parse_toml_text("steps = 4\nstpes = 5\n", "typo.toml");
    TomlSection s(doc, "typo.toml", "");
    int steps = 0;
    s.read("steps", steps);
    const std::string m = test::error_message([&] { s.refuse_unknown_keys(); });
    EXPECT_TRUE(test::contains(m, "typo.toml") && test::contains(m, "stpes")) << m;
}

TEST(TomlSection, ParseErrorsNameTheSource) {
    std::string m = test::error_message([] { parse_toml_text("steps = = 4\n", "broken.toml"); });
    EXPECT_TRUE(test::contains(m, "broken.toml") && test::contains(m, "toml")) << m;
    const std::string dir = test::scratch_dir("toml_section");
    m = test::error_message([&] { parse_toml_file(dir + "/absent.toml"); });
    EXPECT_TRUE(test::contains(m, dir + "/absent.toml")) << m;
}
