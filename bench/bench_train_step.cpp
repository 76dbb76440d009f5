// One training step of the default model (MDM 4 x 256 + the GloVe text encoder, experiments/train-default.toml)
// on the shared motion capture's dataset, at batch 64 and 256, three ways on the same batches (the same seed),
// all the machine's cores, in one benchmark process:
//   old   the loop as it was at 70e56c2: libtorch's TransformerEncoder and Dropout, float32, one EMA kernel
//         pair per tensor (legacy_mdm.hpp and legacy_steps below: that commit's model and loop body, restated)
//   fp32  today's loop (train_mdm) in float32: our encoder (nn/transformer_encoder.hpp) and hashed dropout
//   bf16  today's loop with the forward's products in bfloat16 (nn/autocast.hpp)
// Each run trains a few steps from a fresh model; the first builds kernels and caches and is left out, and so
// is the final model write of train_mdm (`log`). Reports samples/s and, for today's loop, each part's share of
// the step (trainer.hpp StepProfile). Needs cache/dataset (scripts/unpack-mocap.sh, `t2imu data build
// --mirror`) and cache/text/glove-100k.safetensors (scripts/setup.sh); skipped without them.
#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <thread>

#include "core/host_memory.hpp"
#include "data/hml3d_dataset.hpp"
#include "diffusion/gaussian_diffusion.hpp"
#include "diffusion/noise_schedule.hpp"
#include "diffusion/trainer.hpp"
#include "legacy_mdm.hpp"
#include "nn/threads.hpp"

using namespace t2imu;

// As the CLI does (cli/main.cpp): freed blocks stay with the process, so a step's large tensors do not fault
// in fresh pages every step. Set before any benchmark allocates.
static const bool kReuseFreedMemory = (keep_freed_memory_for_reuse(), true);

namespace {

// 70e56c2's loop body on one process: returns the seconds of steps 2..steps.
double legacy_steps(const TrainConfig& c, int64_t steps) {
    Hml3dDataset data(c.dataset, c.split);
    data.seed(c.seed);
    const WordVectors vocab = WordVectors::load(c.vocab);
    torch::manual_seed(c.seed);
    MdmConfig mc = c.mdm;
    mc.text_dim = c.text.out_dim;
    LegacyMdm mdm(mc);
    GloveTextEncoder text(vocab, c.text);
    std::vector<torch::Tensor> params = mdm->parameters();
    for (const torch::Tensor& p : text->parameters()) params.push_back(p);
    torch::optim::AdamW optimiser(params, torch::optim::AdamWOptions(c.learning_rate).weight_decay(c.weight_decay));
    std::vector<torch::Tensor> ema;
    for (const torch::Tensor& p : params) ema.push_back(p.detach().clone());
    const GaussianDiffusion diffusion(cosine_schedule(c.diffusion_steps));
    const torch::Tensor mean =
        torch::from_blob(const_cast<double*>(data.stats().mean.data()), {263}, torch::kFloat64).to(torch::kFloat32);
    const torch::Tensor std =
        torch::from_blob(const_cast<double*>(data.stats().std.data()), {263}, torch::kFloat64).to(torch::kFloat32);
    torch::Generator generator = at::detail::createCPUGenerator(c.seed);
    std::mt19937_64 rng(c.seed + 1);
    std::bernoulli_distribution drop(c.cond_dropout);
    auto start = std::chrono::steady_clock::now();
    for (int64_t step = 0; step < steps; ++step) {
        if (step == 1) start = std::chrono::steady_clock::now();
        const Batch b = data.next_batch(c.batch);
        std::vector<std::string> captions = b.captions;
        for (std::string& caption : captions)
            if (drop(rng)) caption.clear();
        const torch::Tensor t = torch::randint(c.diffusion_steps, {b.size}, generator, torch::kInt64);
        const torch::Tensor noise = torch::randn({b.size, b.channels, 1, b.frames}, generator);
        const torch::Tensor x0 =
            torch::from_blob(const_cast<float*>(b.features.data()), {b.size, b.frames, b.channels}, torch::kFloat32)
                .clone();
        const torch::Tensor lengths = torch::tensor(std::vector<int64_t>(b.lengths.begin(), b.lengths.end()));
        const torch::Tensor x_t = diffusion.q_sample(x0.permute({0, 2, 1}).unsqueeze(2), t, noise);
        const torch::Tensor x0_hat =
            mdm->forward(x_t, t, text->encode(captions), lengths).squeeze(2).permute({0, 2, 1});
        const LossTerms terms = mdm_loss_terms(x0, x0_hat, lengths, mean, std, c);
        optimiser.zero_grad();
        terms.total.backward();
        optimiser.step();
        torch::NoGradGuard no_grad;
        const double decay = ema_decay_at(c.ema_decay, step);
        for (size_t i = 0; i < params.size(); ++i) ema[i].mul_(decay).add_(params[i].detach(), 1 - decay);
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

// range(0): batch; range(1): 0 old, 32 fp32, 16 bf16.
static void BM_TrainStep(benchmark::State& state) {
    const std::string root = T2IMU_SOURCE_DIR;
    if (!std::filesystem::exists(root + "/cache/dataset/summary.json") ||
        !std::filesystem::exists(root + "/cache/text/glove-100k.safetensors")) {
        state.SkipWithError(
            "needs cache/dataset and cache/text/glove-100k.safetensors (scripts/setup.sh, then t2imu data build)");
        return;
    }
    TrainConfig c = read_train_config(root + "/experiments/train-default.toml");
    c.dataset = root + "/cache/dataset";
    c.vocab = root + "/cache/text/glove-100k.safetensors";
    c.out = (std::filesystem::temp_directory_path() / "t2imu-bench-train-step").string();
    c.batch = static_cast<int>(state.range(0));
    const int64_t path = state.range(1);
    c.precision = path == 16 ? "bf16" : "fp32";
    c.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    c.save_every = c.log_every = 1000000;
    const int64_t steps = c.batch >= 256 ? 3 : 6;
    StepProfile p;
    double seconds = 0;
    for (auto _ : state) {
        if (path == 0) {
            set_torch_threads(c.threads);
            seconds = legacy_steps(c, steps);
        } else {
            std::filesystem::remove_all(c.out);
            p = train_mdm(c, false, "", steps).profile;
            seconds = p.total() - p.log;
        }
        state.SetIterationTime(seconds);
    }
    std::filesystem::remove_all(c.out);
    const double n = static_cast<double>(steps - 1), step = seconds / n;
    state.SetLabel(path == 0 ? "old (70e56c2)" : c.precision);
    state.counters["samples/s"] = c.batch / step;
    if (path == 0) return;
    for (const auto& [name, part] : {std::pair<const char*, double>{"data%", p.data},
                                     {"text%", p.text},
                                     {"fwd%", p.forward},
                                     {"bwd%", p.backward},
                                     {"opt%", p.optimiser},
                                     {"ema%", p.ema}})
        state.counters[name] = 100 * part / n / step;
}
BENCHMARK(BM_TrainStep)
    ->ArgsProduct({{64, 256}, {0, 32, 16}})
    ->ArgNames({"batch", "path"})
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
