// t2imu train | finetune: MDM with the default text encoder on a HumanML3D-layout dataset (trainer.hpp).
#include <csignal>
#include <cstdio>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/output_path.hpp"
#include "diffusion/trainer.hpp"

namespace t2imu::cli {

namespace {

void on_stop_signal(int) { request_training_stop(); }

void run(const std::string& config_path, bool resume, const std::string& from, int64_t steps_override, double max_minutes) {
    TrainConfig c = read_train_config(config_path);
    check_usage([&] {
        check_output_path(c.out, config_path + ": out");
        if (!(max_minutes >= 0 && max_minutes < 1e7)) throw Error("--max-minutes", "minutes", "0 (no budget) or more", std::to_string(max_minutes));
    });
    c.max_minutes = max_minutes;
    c.threads = worker_threads();
    c.device = global_options().device;
    c.processes = read_process_group_env();  // torchrun's RANK, WORLD_SIZE, MASTER_ADDR, MASTER_PORT, LOCAL_RANK
    // Ctrl-C or a scheduler's SIGTERM: finish the step, save, exit normally (resume with --resume).
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
    if (steps_override > 0) c.steps = steps_override;
    const TrainProgress p = train_mdm(c, resume, from);
    if (c.processes.rank == 0)
        std::printf("%s: step %lld, last loss %.5f%s\n", c.out.c_str(), static_cast<long long>(p.step), p.loss,
                    p.stopped_early ? " (stopped early and saved: continue with --resume)" : "");
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
    static std::string config, from;
    static bool resume = false;
    static int64_t steps = 0;
    static double max_minutes = 0;
    train->add_option("--config", config, "training configuration (TOML)")->required()->check(CLI::ExistingFile);
    train->add_flag("--resume", resume, "continue from the model folder's checkpoint.pt");
    train->add_option("--steps", steps, "override train.steps");
    train->add_option("--max-minutes", max_minutes, "stop after the step that reaches this wall time, saving model and checkpoint (0: no budget)");
    train->footer(kProcessesHelp);
    train->callback([] { run(config, resume, "", steps, max_minutes); });

    auto* finetune = root.add_subcommand("finetune", "start from a trained model folder (e.g. adding lambda_acc) with a fresh optimiser");
    finetune->add_option("--from", from, "the model folder to start from")->required()->check(CLI::ExistingDirectory);
    finetune->add_option("--config", config, "fine-tuning configuration (TOML; its out is the new folder)")->required()->check(CLI::ExistingFile);
    finetune->add_flag("--resume", resume, "continue an interrupted fine-tuning from its checkpoint");
    finetune->add_option("--steps", steps, "override train.steps");
    finetune->add_option("--max-minutes", max_minutes, "stop after the step that reaches this wall time, saving model and checkpoint (0: no budget)");
    finetune->footer(kProcessesHelp);
    finetune->callback([] { run(config, resume, resume ? "" : from, steps, max_minutes); });
});

}  // namespace t2imu::cli
