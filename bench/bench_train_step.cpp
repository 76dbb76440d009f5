// One training step of the default model (MDM 4 x 256 + the GloVe text encoder, experiments/train-default.toml)
// on the shared motion capture's dataset, at batch 64 and 256, three ways on the same batches (the same seed),
// all the machine's cores, in one benchmark process:
//   old   the loop as it was at 70e56c2: libtorch's TransformerEncoder and Dropout, float32, one EMA kernel
//         pair per tensor (LegacyMdm and legacy_steps below: that commit's model and loop body, restated here)
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
#include "nn/threads.hpp"

using namespace t2imu;

// As the CLI does (cli/main.cpp): freed blocks stay with the process, so a step's large tensors do not fault
// in fresh pages every step. Set before any benchmark allocates.
static const bool kReuseFreedMemory = (keep_freed_memory_for_reuse(), true);

namespace {

// MDM's forward as at 70e56c2 (src/diffusion/mdm.cpp then): libtorch's modules.
struct LegacyMdmImpl : torch::nn::Module {
    explicit LegacyMdmImpl(const MdmConfig& c) : c_(c) {
        namespace nn = torch::nn;
        pose_embedding = register_module("pose", nn::Linear(c.njoints, c.latent_dim));
        time_embed = register_module("time", nn::Sequential(nn::Linear(c.latent_dim, c.latent_dim), nn::SiLU(), nn::Linear(c.latent_dim, c.latent_dim)));
        embed_text = register_module("text", nn::Linear(c.text_dim, c.latent_dim));
        auto layer = nn::TransformerEncoderLayer(
            nn::TransformerEncoderLayerOptions(c.latent_dim, c.num_heads).dim_feedforward(c.ff_size).dropout(c.dropout).activation(torch::kGELU));
        encoder = register_module("encoder", nn::TransformerEncoder(nn::TransformerEncoderOptions(layer, c.num_layers)));
        pose_final = register_module("final", nn::Linear(c.latent_dim, c.njoints));
        pos_dropout = register_module("pos_dropout", nn::Dropout(c.dropout));
        const torch::Tensor pos = torch::arange(c.max_len, torch::kFloat).unsqueeze(1);
        const torch::Tensor div = torch::exp(torch::arange(0, c.latent_dim, 2, torch::kFloat) * (-std::log(10000.0) / static_cast<double>(c.latent_dim)));
        pe = torch::stack({torch::sin(pos * div), torch::cos(pos * div)}, 2).flatten(1).unsqueeze(1);
    }
    torch::Tensor forward(const torch::Tensor& x, const torch::Tensor& t, const torch::Tensor& text, const torch::Tensor& lengths) {
        const int64_t frames = x.size(3);
        const torch::Tensor emb = time_embed->forward(pe.index_select(0, t).squeeze(1)).unsqueeze(0) + embed_text->forward(text).unsqueeze(0);
        torch::Tensor seq = torch::cat({emb, pose_embedding->forward(x.squeeze(2).permute({2, 0, 1}))}, 0);
        seq = pos_dropout->forward(seq + pe.index({torch::indexing::Slice(0, frames + 1)}));
        const torch::Tensor pad = torch::arange(frames).unsqueeze(0) >= lengths.unsqueeze(1);
        const torch::Tensor padding = torch::cat({torch::zeros({x.size(0), 1}, pad.options()), pad}, 1);
        const torch::Tensor out = encoder->forward(seq, {}, padding).index({torch::indexing::Slice(1, torch::indexing::None)});
        return pose_final->forward(out).permute({1, 2, 0}).unsqueeze(2);
    }
    MdmConfig c_;
    torch::nn::Linear pose_embedding{nullptr}, embed_text{nullptr}, pose_final{nullptr};
    torch::nn::Sequential time_embed{nullptr};
    torch::nn::TransformerEncoder encoder{nullptr};
    torch::nn::Dropout pos_dropout{nullptr};
    torch::Tensor pe;
};
TORCH_MODULE(LegacyMdm);

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
    const torch::Tensor mean = torch::from_blob(const_cast<double*>(data.stats().mean.data()), {263}, torch::kFloat64).to(torch::kFloat32);
    const torch::Tensor std = torch::from_blob(const_cast<double*>(data.stats().std.data()), {263}, torch::kFloat64).to(torch::kFloat32);
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
        const torch::Tensor x0 = torch::from_blob(const_cast<float*>(b.features.data()), {b.size, b.frames, b.channels}, torch::kFloat32).clone();
        const torch::Tensor lengths = torch::tensor(std::vector<int64_t>(b.lengths.begin(), b.lengths.end()));
        const torch::Tensor x_t = diffusion.q_sample(x0.permute({0, 2, 1}).unsqueeze(2), t, noise);
        const torch::Tensor x0_hat = mdm->forward(x_t, t, text->encode(captions), lengths).squeeze(2).permute({0, 2, 1});
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
    if (!std::filesystem::exists(root + "/cache/dataset/summary.json") || !std::filesystem::exists(root + "/cache/text/glove-100k.safetensors")) {
        state.SkipWithError("needs cache/dataset and cache/text/glove-100k.safetensors (scripts/setup.sh, then t2imu data build)");
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
    for (const auto& [name, part] : {std::pair<const char*, double>{"data%", p.data}, {"text%", p.text}, {"fwd%", p.forward},
                                     {"bwd%", p.backward}, {"opt%", p.optimiser}, {"ema%", p.ema}})
        state.counters[name] = 100 * part / n / step;
}
BENCHMARK(BM_TrainStep)->ArgsProduct({{64, 256}, {0, 32, 16}})->ArgNames({"batch", "path"})->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
