// t2imu: text to synthetic IMU data. The subcommands live in src/cli/cmd_*.cpp (see command.hpp).
#include <cstdio>
#include <thread>
#include <vector>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/error.hpp"
#include "core/host_memory.hpp"
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

static GlobalOptions g_options;
const GlobalOptions& global_options() { return g_options; }

int worker_threads() {
    if (g_options.threads > 0) return g_options.threads;
    const unsigned n = std::thread::hardware_concurrency();
    return n ? static_cast<int>(n) : 1;
}

}  // namespace t2imu::cli

int main(int argc, char** argv) {
    using namespace t2imu::cli;
    t2imu::keep_freed_memory_for_reuse();
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
