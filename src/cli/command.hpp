// The command table of the t2imu binary. Each src/cli/cmd_*.cpp file adds its subcommands with a static
// CommandRegistrar, so main.cpp needs no list of them. A command parses its options, checks them (usage.hpp: exit 2),
// calls the library and prints; an Error thrown while working becomes one line and exit code 1.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <string>

namespace t2imu::cli {

using CommandAdder = std::function<void(CLI::App& root)>;

struct CommandRegistrar {
    explicit CommandRegistrar(CommandAdder add);
};

// The subcommand `name` of `parent`, created with `description` the first time it is asked for, so that
// several files can add commands under one group ("motion features", "motion import", ...).
CLI::App& command_group(CLI::App& parent, const std::string& name, const std::string& description);

// Storage for a command's option values, made each time the command table is built (not a static), so that one
// process can parse several command lines, each from the defaults (main.cpp's batch mode for the test suite).
void keep_until_next_command_line(std::shared_ptr<void> values);
template <class T>
T& option_values(T initial = T{}) {
    auto values = std::make_shared<T>(std::move(initial));
    keep_until_next_command_line(values);
    return *values;
}

// Options every command shares, set before the command's callback runs.
struct GlobalOptions {
    int threads = 0;             // 0: all cores
    bool verbose = false;        // progress and details on stderr even when it is not a terminal
    std::string device = "cpu";  // where libtorch models run: cpu, cuda or cuda:N (needs a CUDA build of libtorch)
};
const GlobalOptions& global_options();
int worker_threads();  // --threads, or all cores when it is 0

}  // namespace t2imu::cli
