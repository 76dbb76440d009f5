// Every subcommand, found from the program's own --help (so a new one is covered the day it is added), refuses
// an unknown option and a call without its required arguments with exit code 2 and one line "t2imu: ...".
// The probes run through test::run_cli_each (one process per core, the help texts read once per test process).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "test_util.hpp"

using namespace t2imu;

namespace {

// Exit 2 and one line "t2imu: ..." for `args`, or what was wrong.
std::string not_one_line_usage_error(const std::string& args, const test::CliResult& r) {
    const bool one_line = std::count(r.output.begin(), r.output.end(), '\n') == 1 && r.output.rfind("t2imu: ", 0) == 0;
    if (r.exit_code == 2 && one_line) return "";
    return args + "\n    -> exit " + std::to_string(r.exit_code) + ": " + r.output.substr(0, 300);
}

}  // namespace

TEST(CliEveryCommand, UnknownOptionsAndMissingRequiredArgumentsAreOneLineUsageErrors) {
    ASSERT_GE(test::cli_leaves().size(), 29u);  // 29 leaf commands on 2026-12-04
    std::vector<std::string> calls;
    int with_required = 0;
    for (const test::CliLeaf& leaf : test::cli_leaves()) {
        calls.push_back(leaf.path + " --no-such-option 1");
        if (leaf.help.find("REQUIRED") == std::string::npos) continue;
        ++with_required;
        calls.push_back(leaf.path);
    }
    EXPECT_GE(with_required, 25);
    const std::vector<test::CliResult> results = test::run_cli_each(calls);
    for (size_t i = 0; i < calls.size(); ++i) EXPECT_EQ(not_one_line_usage_error(calls[i], results[i]), "");
}

namespace {

// Arguments a stand-in cannot give: one of two options a command needs (--loso or --test...), an option required
// in one mode (catch22's --out with --dataset), a required choice checked after parsing (--to). A minimal call
// adds them, so that it gets past those checks to the option under test. DIR, FILE, OUT: the scratch stand-ins.
struct KnownArgument {
    std::string leaf, option, value;
};
const std::vector<KnownArgument> kKnownArguments = {
    {"har run", "--loso", ""},
    {"sample", "--prompt", "x"},
    {"features catch22", "--dataset", "DIR"},
    {"features catch22", "--out", "OUT"},
    {"motion activity", "--reference", "FILE"},
    {"analysis lacc", "--tau", "0.5"},
    {"data reframe", "--to", "sisfall"},
    {"data import-imu", "--format", "sisfall"},
};

// A call that satisfies the parser: each required argument a stand-in of its type (an empty file, an empty
// folder, the first choice, a word; --out inside `dir`), then `extra`.
std::string minimal_call(const std::string& leaf, const std::vector<test::CliOption>& options, const std::string& dir,
                         const std::string& extra) {
    const auto given_by_extra = [&](const std::string& option) { return extra.rfind(option + " ", 0) == 0; };
    const auto known = [&](const std::string& option) {
        return std::any_of(kKnownArguments.begin(), kKnownArguments.end(),
                           [&](const KnownArgument& k) { return k.leaf == leaf && k.option == option; });
    };
    std::string call = leaf;
    for (const KnownArgument& k : kKnownArguments) {
        if (k.leaf != leaf || given_by_extra(k.option)) continue;
        std::string value = k.value == "DIR"    ? dir + "/d"
                            : k.value == "FILE" ? dir + "/f"
                            : k.value == "OUT"  ? dir + "/o"
                                                : k.value;
        call += " " + k.option + (value.empty() ? "" : " " + value);
    }
    for (const test::CliOption& o : options) {
        if (!o.required || given_by_extra(o.name) || known(o.name)) continue;
        std::string value = "x";
        if (o.name == "--out")
            value = dir + "/o";
        else if (o.type.find(":FILE") != std::string::npos)
            value = dir + "/f";
        else if (o.type.find(":DIR") != std::string::npos || o.type.find(":PATH") != std::string::npos)
            value = dir + "/d";
        else if (o.type.find(":{") != std::string::npos)
            value = o.type.substr(o.type.find(":{") + 2,
                                  o.type.find_first_of(",}", o.type.find(":{")) - o.type.find(":{") - 2);
        call += " " + (o.positional ? "" : o.name + " ") + value;
    }
    return call + " " + extra;
}

}  // namespace

// Every number option of every subcommand refuses nan and an absurd 1e12 with exit 2 and one line naming the
// option, before any work (the other arguments are stand-ins that would fail if read); every --out that cannot
// be made is refused the same way, and nothing is written. Each probe has its own scratch folder.
TEST(CliEveryCommand, NanHugeNumbersAndAnUnwritableOutAreOneLineUsageErrors) {
    const std::string scratch = test::scratch_dir("cli_every_command");
    std::vector<std::string> calls, names, dirs;
    const auto probe = [&](const std::string& leaf, const std::vector<test::CliOption>& options,
                           const std::string& extra, const std::string& name) {
        const std::string dir = scratch + "/p" + std::to_string(calls.size());
        std::filesystem::create_directories(dir + "/d");
        std::ofstream(dir + "/f") << "";
        calls.push_back(minimal_call(leaf, options, dir, extra));
        names.push_back(name);
        dirs.push_back(dir);
    };
    for (const test::CliLeaf& leaf : test::cli_leaves()) {
        const std::vector<test::CliOption> options = test::cli_options_of(leaf.path);
        for (const test::CliOption& o : options) {
            if (o.positional || o.name == "--threads") continue;
            if (o.type.rfind("FLOAT", 0) == 0) probe(leaf.path, options, o.name + " nan", o.name);
            if (o.type.rfind("FLOAT", 0) == 0 || o.type.rfind("INT", 0) == 0)
                probe(leaf.path, options, o.name + " 1e12", o.name);
            if (o.name == "--out") probe(leaf.path, options, "--out /proc/t2imu-no/o", "--out");
        }
    }
    EXPECT_GE(calls.size(), 60u);
    const std::vector<test::CliResult> results = test::run_cli_each(calls);
    for (size_t i = 0; i < calls.size(); ++i) {
        const std::string wrong = not_one_line_usage_error(calls[i], results[i]);
        if (!wrong.empty())
            ADD_FAILURE() << wrong;
        else if (results[i].output.find(names[i]) == std::string::npos)
            ADD_FAILURE() << calls[i] << "\n    -> does not name " << names[i] << ": " << results[i].output;
        if (std::filesystem::exists(dirs[i] + "/o"))
            ADD_FAILURE() << calls[i] << "\n    -> wrote its --out before refusing";
    }
}

// The probes' batch mode (test::run_cli_each) builds a command table per command line: an option set by one call
// is back at its default for the next, and each call keeps its own exit code and output.
TEST(CliEveryCommand, BatchModeStartsEachCommandLineFromTheDefaults) {
    if (std::getenv("T2IMU_TEST_BINARY")) GTEST_SKIP() << "another build: its calls run one process each";
    const std::string joints = test::source_dir() + "/README.md";
    const std::vector<test::CliResult> r = test::run_cli_each(
        {"imu synth --joints " + joints + " --fps 7 --rate 9 --out /proc/t2imu-no/o", "imu synth --help", "--version",
         "imu synth --joints " + joints + " --fps 7 --rate 9 --out /proc/t2imu-no/o", "imu synth --help"});
    ASSERT_EQ(r.size(), 5u);
    for (size_t i : {0, 3}) {
        EXPECT_EQ(r[i].exit_code, 2) << r[i].output;
        EXPECT_TRUE(test::contains(r[i].output, "/proc/t2imu-no")) << r[i].output;
    }
    for (size_t i : {1, 4}) {
        EXPECT_EQ(r[i].exit_code, 0);
        EXPECT_TRUE(test::contains(r[i].output, "--fps FLOAT=20 ")) << r[i].output;
        EXPECT_TRUE(test::contains(r[i].output, "--rate FLOAT=50 ")) << r[i].output;
    }
    EXPECT_EQ(r[2].exit_code, 0);
    EXPECT_EQ(r[2].output, "t2imu 0.1.0\n");
}
