// t2imu experiment: the paper's experiment on the data we hold, from one config (experiments/paper.toml).
#include <cstdio>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/output_path.hpp"
#include "pipeline/experiment.hpp"

namespace t2imu::cli {

static CommandRegistrar registrar([](CLI::App& root) {
    auto* cmd = root.add_subcommand(
        "experiment",
        "synthetic data per source and real set -> HAR synthetic-to-real (repeats), catch22 domain gap, "
        "t-SNE, real-to-real ceiling, L_acc per category -> summary.md and report; resumable");
    auto& config = option_values<std::string>();
    auto& out = option_values<std::string>();
    auto& repeats = option_values<int>(0);
    cmd->add_option("--config", config, "experiment TOML (experiments/paper.toml)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--out", out, "results folder; rerun with the same folder to continue")->required();
    cmd->add_option("--repeats", repeats, "HAR trainings per row (default: the config's har.repeats)");
    cmd->callback([&config, &out, &repeats] {
        check_usage([&config, &out, &repeats] {
            if (repeats < 0 || repeats > 1000)
                throw Error("--repeats", "trainings", "0 (the config's) to 1000", std::to_string(repeats));
            check_output(out, "--out", OutputKind::folder, {config});
        });
        ExperimentConfig c = read_experiment_config(config);
        if (repeats > 0) c.har.repeats = repeats;
        c.synth.device = global_options().device;
        c.synth.threads = worker_threads();
        const ExperimentSummary summary = run_experiment(
            plan_experiment(c, out), [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
        std::printf("%s", experiment_summary_markdown(summary).c_str());
    });
});

}  // namespace t2imu::cli
