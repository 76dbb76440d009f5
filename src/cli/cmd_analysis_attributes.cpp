// t2imu analysis attributes: the attribute benchmark (analysis/attribute_benchmark.hpp) on a synth folder: do
// the prompts' words for speed, turns, direction and sequences reach the motions drawn for them?
#include <cstdio>

#include "analysis/attribute_benchmark.hpp"
#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/atomic_file.hpp"
#include "core/output_path.hpp"

namespace t2imu::cli {

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& analysis = command_group(root, "analysis", "evaluation analyses");
    auto* cmd = analysis.add_subcommand(
        "attributes",
        "attribute benchmark of a synth folder: speed ratio fast / slow, turns, backward, sequences (JSON)");
    auto& synth = option_values<std::string>();
    auto& out = option_values<std::string>();
    cmd->add_option("--synth", synth, "t2imu synth folder (e.g. of prompts/attributes.tsv, --no-filter)")
        ->required()
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--out", out, "RESULT.json (default: print the table only)");
    cmd->callback([&out, &synth] {
        check_usage([&out, &synth] {
            if (!out.empty()) check_output(out, "--out", OutputKind::file, {synth});
        });
        const AttributeBenchmark b = attribute_benchmark(synth_folder_draws(synth));
        std::fputs(attribute_benchmark_table(b).c_str(), stdout);
        if (!out.empty()) write_file_atomic(out, attribute_benchmark_json(b));
    });
});

}  // namespace t2imu::cli
