// Every subcommand, found from the program's own --help (so a new one is covered the day it is added), refuses
// an unknown option and a call without its required arguments with exit code 2 and one line "t2imu: ...".
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
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

namespace {

struct OptionLine {
    std::string name, type;  // "--window", "FLOAT=2" / "TEXT:DIR" / "TEXT:{a,b}"
    bool required = false, positional = false;
};

// The options and positionals of `t2imu LEAF --help`, as CLI11 lists them.
std::vector<OptionLine> options_of(const std::string& leaf) {
    std::vector<OptionLine> out;
    std::istringstream in(test::run_cli(leaf + " --help").output);
    bool listing = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("Options:", 0) == 0 || line.rfind("Positionals:", 0) == 0) {
            listing = true;
            continue;
        }
        if (!listing || line.size() < 3 || line[0] != ' ' || line[2] == ' ') continue;
        std::istringstream words(line);
        OptionLine o;
        words >> o.name >> o.type;
        if (o.name.rfind("-h,", 0) == 0 || (o.name.rfind("--", 0) != 0 && o.name[0] == '-')) continue;  // help, short-only flags
        o.positional = o.name[0] != '-';
        o.required = line.find("REQUIRED") != std::string::npos;
        out.push_back(o);
    }
    return out;
}

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
};

// A call that satisfies the parser: each required argument a stand-in of its type (an empty file, an empty
// folder, the first choice, a word; --out inside `dir`), then `extra`.
std::string minimal_call(const std::string& leaf, const std::vector<OptionLine>& options, const std::string& dir, const std::string& extra) {
    const auto given_by_extra = [&](const std::string& option) { return extra.rfind(option + " ", 0) == 0; };
    const auto known = [&](const std::string& option) {
        return std::any_of(kKnownArguments.begin(), kKnownArguments.end(), [&](const KnownArgument& k) { return k.leaf == leaf && k.option == option; });
    };
    std::string call = leaf;
    for (const KnownArgument& k : kKnownArguments) {
        if (k.leaf != leaf || given_by_extra(k.option)) continue;
        std::string value = k.value == "DIR" ? dir + "/d" : k.value == "FILE" ? dir + "/f" : k.value == "OUT" ? dir + "/o" : k.value;
        call += " " + k.option + (value.empty() ? "" : " " + value);
    }
    for (const OptionLine& o : options) {
        if (!o.required || given_by_extra(o.name) || known(o.name)) continue;
        std::string value = "x";
        if (o.name == "--out") value = dir + "/o";
        else if (o.type.find(":FILE") != std::string::npos) value = dir + "/f";
        else if (o.type.find(":DIR") != std::string::npos || o.type.find(":PATH") != std::string::npos) value = dir + "/d";
        else if (o.type.find(":{") != std::string::npos) value = o.type.substr(o.type.find(":{") + 2, o.type.find_first_of(",}", o.type.find(":{")) - o.type.find(":{") - 2);
        call += " " + (o.positional ? "" : o.name + " ") + value;
    }
    return call + " " + extra;
}

}  // namespace

// Every number option of every subcommand refuses nan and an absurd 1e12 with exit 2 and one line naming the
// option, before any work (the other arguments are stand-ins that would fail if read); every --out that cannot
// be made is refused the same way, and nothing is written.
TEST(CliEveryCommand, NanHugeNumbersAndAnUnwritableOutAreOneLineUsageErrors) {
    std::vector<std::string> leaves;
    collect_leaves("", &leaves);
    const std::string dir = test::scratch_dir("cli_every_command");
    std::ofstream(dir + "/f") << "";
    std::filesystem::create_directories(dir + "/d");
    std::vector<std::string> failures;
    int probes = 0;
    const auto probe = [&](const std::string& args, const std::string& names) {
        ++probes;
        const test::CliResult r = test::run_cli(args);
        const bool one_line = std::count(r.output.begin(), r.output.end(), '\n') == 1 && r.output.rfind("t2imu: ", 0) == 0;
        if (r.exit_code != 2 || !one_line || r.output.find(names) == std::string::npos)
            failures.push_back(args + "\n    -> exit " + std::to_string(r.exit_code) + ": " + r.output.substr(0, 300));
        if (std::filesystem::exists(dir + "/o")) failures.push_back(args + "\n    -> wrote its --out before refusing");
        std::filesystem::remove_all(dir + "/o");
    };
    for (const std::string& leaf : leaves) {
        const std::vector<OptionLine> options = options_of(leaf);
        for (const OptionLine& o : options) {
            if (o.positional || o.name == "--threads") continue;
            if (o.type.rfind("FLOAT", 0) == 0) probe(minimal_call(leaf, options, dir, o.name + " nan"), o.name);
            if (o.type.rfind("FLOAT", 0) == 0 || o.type.rfind("INT", 0) == 0) probe(minimal_call(leaf, options, dir, o.name + " 1e12"), o.name);
            if (o.name == "--out") probe(minimal_call(leaf, options, dir, "--out /proc/t2imu-no/o"), "--out");
        }
    }
    EXPECT_GE(probes, 60);
    for (const std::string& f : failures) ADD_FAILURE() << f;
}
