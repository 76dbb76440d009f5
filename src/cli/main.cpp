// t2imu: text to synthetic IMU data. The subcommands live in src/cli/cmd_*.cpp (see command.hpp).
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <thread>
#include <vector>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/error.hpp"
#include "core/host_memory.hpp"
#include "core/parse.hpp"
#include "core/progress.hpp"
#include "nn/threads.hpp"

namespace t2imu::cli {

static std::vector<CommandAdder>& command_adders() {
    static std::vector<CommandAdder> adders;
    return adders;
}

CommandRegistrar::CommandRegistrar(CommandAdder add) { command_adders().push_back(std::move(add)); }

CLI::App& command_group(CLI::App& parent, const std::string& name, const std::string& description) {
    for (CLI::App* sub : parent.get_subcommands([](CLI::App*) { return true; }))
        if (sub->get_name() == name) return *sub;
    CLI::App* group = parent.add_subcommand(name, description);
    group->require_subcommand(1);
    return *group;
}

static std::vector<std::shared_ptr<void>>& option_storage() {
    static std::vector<std::shared_ptr<void>> storage;
    return storage;
}

void keep_until_next_command_line(std::shared_ptr<void> values) { option_storage().push_back(std::move(values)); }

static GlobalOptions g_options;
const GlobalOptions& global_options() { return g_options; }

int worker_threads() {
    if (g_options.threads > 0) return g_options.threads;
    const unsigned n = std::thread::hardware_concurrency();
    return n ? static_cast<int>(n) : 1;
}

}  // namespace t2imu::cli

namespace {

using namespace t2imu::cli;

// One command line, parsed by a command table built for it from the defaults; the exit code.
int run_command_line(int argc, char** argv) {
    option_storage().clear();  // the values of the last command line's table, which is gone
    g_options = GlobalOptions{};
    t2imu::set_progress_output(t2imu::ProgressOutput::terminal_only);
    CLI::App app{"t2imu: text to realistic synthetic IMU data, and how realistic it is"};
    app.set_version_flag("--version", "t2imu 0.1.0");
    app.require_subcommand(1);
    // Help shows each option's default as the bound library object holds it, so the defaults live in one place.
    app.option_defaults()->always_capture_default();
    app.add_option("--threads", g_options.threads, "worker threads, libtorch's included (0: all cores)")
        ->check(CLI::NonNegativeNumber)
        ->each([](const std::string&) { t2imu::set_torch_threads(worker_threads()); });
    app.add_flag("-v,--verbose", g_options.verbose, "progress and details on stderr, also in a pipe")
        ->each([](const std::string&) { t2imu::set_progress_output(t2imu::ProgressOutput::always); });
    app.add_option("--device", g_options.device, "where the diffusion model trains and samples: cpu, cuda, cuda:N")
        ->check([](const std::string& d) {
            return d == "cpu" || d.rfind("cuda", 0) == 0 ? std::string() : std::string("cpu, cuda or cuda:N");
        });
    app.fallthrough();
    for (const CommandAdder& add : command_adders()) add(app);
    t2imu::set_torch_threads(worker_threads());
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help and --version print what was asked for
        // One line, like every other error (CLI11 would add a second one pointing at --help); what it quotes of the
        // arguments is made printable and cut like an Error's.
        std::fprintf(stderr, "t2imu: %s\n", t2imu::printable_text(e.what(), 2000).c_str());
        return 2;
    } catch (const UsageError& e) {
        std::fprintf(stderr, "t2imu: %s\n", e.what());
        return 2;
    } catch (const t2imu::Error& e) {
        std::fprintf(stderr, "t2imu: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "t2imu: %s\n", t2imu::printable_text(e.what(), 2000).c_str());
        return 1;
    }
    return 0;
}

void flush_all() {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(stdout);
    std::fflush(stderr);
}

// T2IMU_CLI_BATCH=1, for the test suite's probes: standard input holds command lines, each its argument count and
// its arguments, every field ended by a NUL; for each, standard output gets "EXIT\nLENGTH\n" and what the command
// printed (stdout and stderr together). One process start serves hundreds of probes (a start loads libtorch's
// shared libraries).
int run_batch() {
    const std::string input((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
    size_t at = 0;
    const auto field = [&] {
        const size_t end = input.find('\0', at);
        if (end == std::string::npos) throw t2imu::Error("T2IMU_CLI_BATCH", "standard input", "NUL-ended fields");
        std::string f = input.substr(at, end - at);
        at = end + 1;
        return f;
    };
    flush_all();
    const int out = dup(1), err = dup(2);
    while (at < input.size()) {
        std::vector<std::string> args = {"t2imu"};
        for (long n = t2imu::integer_in(field(), 0, 10000, "T2IMU_CLI_BATCH", "argument count"); n > 0; --n)
            args.push_back(field());
        std::vector<char*> argv;
        for (std::string& a : args) argv.push_back(a.data());
        std::FILE* capture = std::tmpfile();
        if (!capture) throw t2imu::Error("T2IMU_CLI_BATCH", "a temporary file", "one that can be made");
        dup2(fileno(capture), 1), dup2(fileno(capture), 2);
        const int code = run_command_line(static_cast<int>(argv.size()), argv.data());
        flush_all();
        dup2(out, 1), dup2(err, 2);
        std::string printed;
        lseek(fileno(capture), 0, SEEK_SET);
        char buf[4096];
        for (ssize_t n; (n = read(fileno(capture), buf, sizeof buf)) > 0;) printed.append(buf, static_cast<size_t>(n));
        std::fclose(capture);
        std::printf("%d\n%zu\n", code, printed.size());
        std::fwrite(printed.data(), 1, printed.size(), stdout);
        std::fflush(stdout);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    t2imu::keep_freed_memory_for_reuse();
    const char* batch = std::getenv("T2IMU_CLI_BATCH");
    if (batch && std::string(batch) == "1") {
        try {
            return run_batch();
        } catch (const t2imu::Error& e) {
            std::fprintf(stderr, "t2imu: %s\n", e.what());
            return 2;
        }
    }
    return run_command_line(argc, argv);
}
