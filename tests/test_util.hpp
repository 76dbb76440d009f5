// Shared helpers of the test suite: where the shared data is, archives unpacked once per build, scratch
// folders, and running the t2imu binary.
#pragma once
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "text/word_vectors.hpp"

namespace t2imu::test {

// ../shared/data beside the checkout, or $T2IMU_SHARED_DATA. Empty when absent.
std::string shared_data_dir();

// The path of `relative` under the shared data; skips the calling test with a clear message when the shared
// data (or that file) is missing. Use as: `std::string p; SHARED_OR_SKIP(p, "mocap/manifest.csv");`
#define SHARED_OR_SKIP(var, relative)                                                              \
    do {                                                                                           \
        var = ::t2imu::test::shared_path(relative);                                                \
        if (var.empty())                                                                           \
            GTEST_SKIP() << "shared data not found: " << (relative)                                \
                         << " (expects ../shared/data beside the checkout or $T2IMU_SHARED_DATA)"; \
    } while (0)
std::string shared_path(const std::string& relative);  // "" when missing

// Unpacks a shared .tar.xz once per build into the test scratch area and returns that folder ("" when the
// archive is missing). Safe to call from many tests.
std::string unpacked_shared_archive(const std::string& relative_archive);

// A fresh, empty scratch folder for one test.
std::string scratch_dir(const std::string& name);

struct CliResult {
    int exit_code;
    std::string output;  // stdout and stderr together
};
// The message of the t2imu::Error that `f` throws, or "no error".
template <class F>
std::string error_message(F f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// Runs the t2imu binary with `args` (a shell-quoted string): this build's, or the one T2IMU_TEST_BINARY names
// (to run the CLI suites against another build, e.g. an old commit's, and see which of its defects they catch).
CliResult run_cli(const std::string& args);
// Runs a shell command line (its stderr joined to stdout), e.g. one of the project's scripts.
CliResult run_shell(const std::string& command);
// run_cli once per argument string, the results in the order of `calls`: the calls run in one t2imu process per core
// (its batch mode, src/cli/main.cpp; a process start costs most of a probe's time), or each in its own process for
// the build T2IMU_TEST_BINARY names.
std::vector<CliResult> run_cli_each(const std::vector<std::string>& calls);

std::string source_dir();

// Every leaf command of the binary as "group sub" paths, sorted, with its help text, read from the "Subcommands:" lists
// of `t2imu [PATH] --help` (so a new command is covered the day it is added); once per process.
struct CliLeaf {
    std::string path;  // "group sub"
    std::string help;  // `t2imu group sub --help`
};
const std::vector<CliLeaf>& cli_leaves();
std::vector<std::string> cli_leaf_commands();
// An option or positional as `t2imu LEAF --help` lists it: "--window FLOAT=2 ...", "--out TEXT:DIR REQUIRED".
struct CliOption {
    std::string name, type, help;  // "--out", "TEXT", the rest of its line
    bool required = false, positional = false;
};
// The options of one of cli_leaves() (none for a path that is not a leaf).
std::vector<CliOption> cli_options_of(const std::string& leaf);

// Whether gnuplot cannot be run (figure tests skip then; scripts/setup.sh installs gnuplot-nox).
bool gnuplot_missing();

// Whether `text` holds `part` (messages, pages, tables).
inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

constexpr double kPi = 3.14159265358979323846;

// The message of the t2imu::Error `f` throws; a test failure and "" when it throws none.
std::string error_message(const std::function<void()>& f);

// Words as given coordinates on the first axes, padded to WordVectors::kDims (use at least three axes: SIF removes
// the captions' common direction, which in a plane would leave every caption on one line).
WordVectors axis_vocabulary(const std::vector<std::pair<std::string, std::vector<float>>>& words);

}  // namespace t2imu::test
