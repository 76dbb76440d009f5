// Every subcommand, found from the program's own --help (so a new one is covered the day it is added), refuses
// an unknown option and a call without its required arguments with exit code 2 and one line "t2imu: ...".
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "test_util.hpp"

using namespace t2imu;

namespace {

// The names listed under "Subcommands:" in `t2imu PATH --help`.
std::vector<std::string> subcommands_of(const std::string& path) {
    const test::CliResult r = test::run_cli(path + " --help");
    std::vector<std::string> names;
    std::istringstream in(r.output);
    bool listing = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("Subcommands:", 0) == 0) {
            listing = true;
            continue;
        }
        if (!listing) continue;
        if (line.size() < 3 || line[0] != ' ' || line[2] == ' ') break;  // the list ends at a blank or unindented line
        std::istringstream words(line);
        std::string name;
        words >> name;
        names.push_back(name);
    }
    return names;
}

// Every leaf command as "group sub" paths, depth first.
void collect_leaves(const std::string& path, std::vector<std::string>* leaves) {
    const std::vector<std::string> children = subcommands_of(path);
    if (children.empty() && !path.empty()) leaves->push_back(path);
    for (const std::string& c : children) collect_leaves(path.empty() ? c : path + " " + c, leaves);
}

void expect_one_line_usage_error(const std::string& args) {
    const test::CliResult r = test::run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << args << "\n" << r.output;
    EXPECT_EQ(r.output.rfind("t2imu: ", 0), 0u) << args << "\n" << r.output;
}

}  // namespace

TEST(CliEveryCommand, UnknownOptionsAndMissingRequiredArgumentsAreOneLineUsageErrors) {
    std::vector<std::string> leaves;
    collect_leaves("", &leaves);
    ASSERT_GE(leaves.size(), 29u);  // 29 leaf commands on 2026-12-04
    int with_required = 0;
    for (const std::string& leaf : leaves) {
        expect_one_line_usage_error(leaf + " --no-such-option 1");
        if (test::run_cli(leaf + " --help").output.find("REQUIRED") == std::string::npos) continue;
        ++with_required;
        expect_one_line_usage_error(leaf);
    }
    EXPECT_GE(with_required, 25);
}
