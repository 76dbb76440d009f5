// t2imu train | finetune: MDM with the default text encoder on a HumanML3D-layout dataset (trainer.hpp).
#include <csignal>
#include <cstdio>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/output_path.hpp"
#include "diffusion/trainer.hpp"
#include "nn/autocast.hpp"

namespace t2imu::cli {

namespace {

void on_stop_signal(int) { request_training_stop(); }

// One line per part: seconds per step and share of the step (trainer.hpp StepProfile).
void print_profile(const StepProfile& p, int batch) {
    if (p.steps == 0) return;
    const double total = p.total(), n = static_cast<double>(p.steps);
    std::printf("profile over %lld steps: %.3f s per step, %.1f samples/s\n", static_cast<long long>(p.steps),
                total / n, batch * n / total);
    const std::pair<const char*, double> parts[] = {
        {"data", p.data},           {"text", p.text}, {"forward", p.forward}, {"backward", p.backward},
        {"optimiser", p.optimiser}, {"ema", p.ema},   {"log", p.log}};
    for (const auto& [name, seconds] : parts)
        std::printf("  %-9s %8.4f s %5.1f %%\n", name, seconds / n, 100 * seconds / total);
}

struct RunOptions {
    std::string config, from, precision;
    bool resume = false, profile = false;
    int64_t steps = 0;
    double max_minutes = 0;
};

void run(const RunOptions& o) {
    // The options first, then the config they override: a bad option is a usage error before any file is read.
    check_usage([&] {
        if (!(o.max_minutes >= 0 && o.max_minutes <= 1e7))
            throw Error("--max-minutes", "minutes", "0 (no budget) to 10^7", std::to_string(o.max_minutes));
        if (o.steps < 0 || o.steps > 1000000000)
            throw Error("--steps", "steps", "0 (the config's) to 10^9", std::to_string(o.steps));
        if (!o.precision.empty()) parse_precision(o.precision, "--precision", "value");
    });
    TrainConfig c = read_train_config(o.config);
    check_usage([&] {
        check_output(c.out, o.config + ": out", OutputKind::folder, {o.config, o.from, c.dataset, c.vocab});
    });
    if (!o.precision.empty()) c.precision = o.precision;
    c.max_minutes = o.max_minutes;
    c.threads = worker_threads();
    c.device = global_options().device;
    c.processes = read_process_group_env();  // torchrun's RANK, WORLD_SIZE, MASTER_ADDR, MASTER_PORT, LOCAL_RANK
    // Ctrl-C or a scheduler's SIGTERM: finish the step, save, exit normally (resume with --resume).
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
    if (o.steps > 0) c.steps = o.steps;
    c.profile = o.profile;
    const TrainProgress p = train_mdm(c, o.resume, o.resume ? "" : o.from);
    if (c.processes.rank != 0) return;
    if (p.steps_run == 0) {
        std::printf(
            "%s: no step ran: the checkpoint is at step %lld and train.steps is %lld (give --steps to go further)\n",
            c.out.c_str(), static_cast<long long>(p.step), static_cast<long long>(c.steps));
        return;
    }
    std::printf("%s: step %lld, last loss %.5f%s\n", c.out.c_str(), static_cast<long long>(p.step), p.loss,
                p.stopped_early ? " (stopped early and saved: continue with --resume)" : "");
    if (o.profile) print_profile(p.profile, c.batch);
}

// Shown under both subcommands' --help.
const char* const kProcessesHelp =
    "Data-parallel over several processes, configured like torchrun by the environment: WORLD_SIZE processes, "
    "each with its RANK (0 .. WORLD_SIZE-1; LOCAL_RANK picks the GPU for --device cuda), meeting at rank 0's "
    "MASTER_ADDR:MASTER_PORT. Each process computes train.batch / WORLD_SIZE samples of every batch (train.batch "
    "must divide evenly); the result equals one process with the whole batch. Gloo on the CPU, NCCL on CUDA "
    "where libtorch has it. Only rank 0 writes the model folder; with --resume every rank reads its checkpoint. "
    "Example, two processes on this machine: RANK=0 WORLD_SIZE=2 MASTER_ADDR=127.0.0.1 MASTER_PORT=29500 "
    "t2imu --threads 1 train --config c.toml & RANK=1 WORLD_SIZE=2 MASTER_ADDR=127.0.0.1 MASTER_PORT=29500 "
    "t2imu --threads 1 train --config c.toml";

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    auto* train = root.add_subcommand("train", "train MDM + the GloVe text encoder (TOML config) into a model folder");
    auto& o = option_values<RunOptions>();
    const auto common = [&o](CLI::App* cmd) {
        cmd->add_option("--steps", o.steps, "override train.steps");
        cmd->add_option("--max-minutes", o.max_minutes,
                        "stop after the step that reaches this wall time, saving model and checkpoint (0: no budget)");
        cmd->add_option("--precision", o.precision,
                        "override train.precision: fp32, or bf16 (the forward's products in bfloat16)");
        cmd->add_flag("--profile", o.profile,
                      "print seconds per step of each part (data, text, forward, backward, optimiser, ema, log)");
        cmd->footer(kProcessesHelp);
        cmd->callback([&o] { run(o); });
    };
    train->add_option("--config", o.config, "training configuration (TOML)")->required()->check(CLI::ExistingFile);
    train->add_flag("--resume", o.resume, "continue from the model folder's checkpoint.pt");
    common(train);

    auto* finetune = root.add_subcommand(
        "finetune", "start from a trained model folder (e.g. adding lambda_acc) with a fresh optimiser");
    finetune->add_option("--from", o.from, "the model folder to start from")->required()->check(CLI::ExistingDirectory);
    finetune->add_option("--config", o.config, "fine-tuning configuration (TOML; its out is the new folder)")
        ->required()
        ->check(CLI::ExistingFile);
    finetune->add_flag("--resume", o.resume, "continue an interrupted fine-tuning from its checkpoint");
    common(finetune);
});

}  // namespace t2imu::cli
