// The output-path guard (core/output_path.hpp) at every command that writes, found from the program's own --help:
// each of its output options against a symbolic link, a "LINK/.." path, a user's non-empty folder, the wrong kind
// (a folder where a file goes, a file where a folder goes), one of its own inputs and a place below /proc is refused
// with exit 2 and one line naming the reason, and nothing in the command's scratch tree changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "core/output_path.hpp"
#include "test_util.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {

// Arguments a stand-in cannot give: one of two options a command needs, a required choice checked after parsing.
// INPUT: the stand-in file; DIR: the stand-in folder.
const std::multimap<std::string, std::string> kExtraArguments = {
    {"har run", "--loso"},
    {"sample", "--prompt x"},
    {"features catch22", "--dataset DIR"},
    {"motion activity", "--reference INPUT"},
    {"analysis lacc", "--tau 0.5"},
    {"data reframe", "--to sisfall"},
    {"motion quality", "INPUT"},
    {"data import-imu", "--format sisfall"},
};
// Commands that write nothing, and those whose output is named in their --config (written by the test below).
const std::vector<std::string> kWriteNothing = {"text similarity"};
const std::vector<std::string> kOutputInConfig = {"train", "finetune"};

struct Probe {
    std::string leaf, args, reason;  // reason: the words the one line must hold
};

// The scratch tree of one command: stand-in inputs and every kind of trap.
void make_tree(const std::string& root) {
    fs::create_directories(root + "/d");
    std::ofstream(root + "/f") << "";
    fs::create_directories(root + "/linked");
    std::ofstream(root + "/linked/" + kOutputMarker) << "\n";
    fs::create_symlink(root + "/linked", root + "/link");
    fs::create_directories(root + "/ot");
    fs::create_directories(root + "/elsewhere/deep");
    fs::create_directories(root + "/elsewhere/victim");
    std::ofstream(root + "/elsewhere/victim/thesis.txt") << "six years\n";
    fs::create_symlink(root + "/elsewhere/deep", root + "/ot/lnkdir");
    fs::create_directories(root + "/users/jobs");
    std::ofstream(root + "/users/manifest.csv") << "mine\n";
    fs::create_directories(root + "/made");
    std::ofstream(root + "/made/" + kOutputMarker) << "\n";
    std::ofstream(root + "/notes.txt") << "mine\n";
}

// Every path below `root` with its link target or bytes.
std::string tree_listing(const std::string& root) {
    std::vector<std::string> lines;
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
        std::string line = it->path().string();
        if (it->is_symlink())
            line += " -> " + fs::read_symlink(it->path()).string();
        else if (it->is_regular_file()) {
            std::ifstream in(it->path(), std::ios::binary);
            line += " = " + std::string(std::istreambuf_iterator<char>(in), {});
        }
        lines.push_back(line);
    }
    std::sort(lines.begin(), lines.end());
    std::string listing;
    for (const std::string& l : lines) listing += l + "\n";
    return listing;
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
    return s;
}

// A call that satisfies the parser with stand-ins (INPUT for files, DIR for folders, the first of a choice),
// leaving out `output` (given by each probe).
std::string minimal_call(const std::string& leaf, const std::vector<test::CliOption>& options,
                         const std::string& output) {
    std::string call = leaf;
    const auto extra = kExtraArguments.equal_range(leaf);
    for (auto e = extra.first; e != extra.second; ++e) call += " " + e->second;
    for (const test::CliOption& o : options) {
        if (!o.required || o.name == output || call.find(" " + o.name + " ") != std::string::npos) continue;
        std::string value = "x";
        if (o.type.find(":FILE") != std::string::npos)
            value = "INPUT";
        else if (o.type.find(":DIR") != std::string::npos || o.type.find(":PATH") != std::string::npos)
            value = "DIR";
        else if (o.type.find(":{") != std::string::npos)
            value = o.type.substr(o.type.find(":{") + 2,
                                  o.type.find_first_of(",}", o.type.find(":{")) - o.type.find(":{") - 2);
        call += " " + (o.positional ? "" : o.name + " ") + value;
    }
    return call;
}

// The six traps for one output option of kind `folder` or file; `input` is the stand-in the call reads.
std::vector<Probe> probes_for(const std::string& leaf, const std::string& call, const std::string& option,
                              bool folder) {
    const std::string input = call.find("INPUT") != std::string::npos ? "INPUT" : "DIR";
    const std::string existing_folder = "an existing folder", foreign = folder ? "did not make" : existing_folder;
    return {{leaf, call + " " + option + " ROOT/link", "symbolic link"},
            {leaf, call + " " + option + " ROOT/ot/lnkdir/../victim", foreign},
            {leaf, call + " " + option + " ROOT/users", foreign},
            {leaf, call + " " + option + (folder ? " ROOT/notes.txt" : " ROOT/made"),
             folder ? "an existing file" : existing_folder},
            {leaf, call + " " + option + " " + input, "input"},
            {leaf, call + " " + option + " /proc/t2imu-probe/out", "/proc/t2imu-probe"}};
}

// train and finetune name their output folder in the config: the same traps, written into it.
std::vector<Probe> config_probes(const std::string& leaf) {
    const std::vector<std::pair<std::string, std::string>> outs = {{"ROOT/link", "symbolic link"},
                                                                   {"ROOT/ot/lnkdir/../victim", "did not make"},
                                                                   {"ROOT/users", "did not make"},
                                                                   {"ROOT/notes.txt", "an existing file"},
                                                                   {"DIR", "input"},
                                                                   {"/proc/t2imu-probe/out", "/proc/t2imu-probe"}};
    std::vector<Probe> probes;
    for (size_t i = 0; i < outs.size(); ++i) {
        const std::string config = "ROOT/config" + std::to_string(i) + ".toml";
        const std::string write = "out = \"" + outs[i].first + "\"\n[data]\ndataset = \"DIR\"\nvocab = \"INPUT\"\n";
        probes.push_back({leaf, "WRITE " + config + " " + write, outs[i].second});
    }
    return probes;
}

}  // namespace

TEST(CliOutputPaths, EveryWritingCommandRefusesEveryTrapBeforeAnyWork) {
    const std::string scratch = test::scratch_dir("cli_output_paths");
    ASSERT_FALSE(fs::exists("/proc/t2imu-probe"));
    std::vector<Probe> probes;
    int writers = 0;
    for (const std::string& leaf : test::cli_leaf_commands()) {
        if (std::find(kWriteNothing.begin(), kWriteNothing.end(), leaf) != kWriteNothing.end()) continue;
        if (std::find(kOutputInConfig.begin(), kOutputInConfig.end(), leaf) != kOutputInConfig.end()) {
            for (const Probe& p : config_probes(leaf)) probes.push_back(p);
            ++writers;
            continue;
        }
        const std::vector<test::CliOption> options = test::cli_options_of(leaf);
        int outputs = 0;
        for (const test::CliOption& o : options) {
            if (o.name != "--out" && o.name != "--save-reference") continue;
            const bool folder =
                o.help.find("folder") != std::string::npos;  // "output folder", "report folder": else a file
            for (const Probe& p : probes_for(leaf, minimal_call(leaf, options, o.name), o.name, folder))
                probes.push_back(p);
            ++outputs;
        }
        EXPECT_GT(outputs, 0) << leaf << ": writes nothing? add it to kWriteNothing, or its output option here";
        writers += outputs > 0;
    }
    EXPECT_GE(writers, 29);  // every leaf command but text similarity

    // One scratch tree per probe; the probes run together through test::run_cli_each.
    std::vector<std::string> calls, roots, before;
    for (size_t i = 0; i < probes.size(); ++i) {
        const Probe& p = probes[i];
        const std::string root = scratch + "/" + std::to_string(i);
        make_tree(root);
        std::string args = replaced(replaced(replaced(p.args, "ROOT", root), "INPUT", root + "/f"), "DIR", root + "/d");
        if (args.rfind("WRITE ", 0) == 0) {  // "WRITE PATH TEXT": the config, then `LEAF --config PATH`
            const size_t end = args.find(' ', 6);
            const std::string config = args.substr(6, end - 6);
            std::ofstream(config) << args.substr(end + 1);
            args = p.leaf + " --config " + config + (p.leaf == "finetune" ? " --from " + root + "/made" : "");
        }
        calls.push_back("--threads 1 " + args);
        roots.push_back(root);
        before.push_back(tree_listing(root));
    }
    const std::vector<test::CliResult> results = test::run_cli_each(calls);
    std::vector<std::string> failures(probes.size());
    for (size_t i = 0; i < probes.size(); ++i) {
        const test::CliResult& r = results[i];
        std::string why;
        if (r.exit_code != 2) why += " exit " + std::to_string(r.exit_code) + ";";
        if (std::count(r.output.begin(), r.output.end(), '\n') != 1 || r.output.rfind("t2imu: ", 0) != 0)
            why += " not one line;";
        if (!test::contains(r.output, probes[i].reason)) why += " no '" + probes[i].reason + "';";
        if (tree_listing(roots[i]) != before[i]) why += " the tree changed;";
        if (!why.empty()) failures[i] = calls[i] + ":" + why + "\n  " + r.output.substr(0, 400);
    }
    for (const std::string& f : failures) EXPECT_TRUE(f.empty()) << f;
    EXPECT_FALSE(fs::exists("/proc/t2imu-probe"));
    EXPECT_GE(probes.size(), 6u * 29);
}
