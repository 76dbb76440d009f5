// One MDM denoiser evaluation with classifier-free guidance (the batched conditional + unconditional pass of
// every sampling step), 120 frames, for the official size (8 layers x 512) and the default training size
// (4 x 256), at batch 1 and 16; libtorch CPU with the benchmark's thread count (see bench/README.md). Today's
// model (sampling takes the fused encoder kernel, nn/transformer_encoder.hpp) and, as Legacy, the model as it
// was up to 70e56c2 (libtorch's TransformerEncoder module, legacy_mdm.hpp), on the same inputs.
#include <benchmark/benchmark.h>

#include "diffusion/mdm.hpp"
#include "legacy_mdm.hpp"

using namespace t2imu;

namespace {

MdmConfig guided_step_config(const benchmark::State& state) {
    MdmConfig c;
    c.latent_dim = state.range(0);
    c.num_layers = state.range(0) == 512 ? 8 : 4;
    c.ff_size = state.range(0) == 512 ? 1024 : 512;
    return c;
}

}  // namespace

static void BM_MdmGuidedStepLegacy(benchmark::State& state) {
    torch::NoGradGuard no_grad;
    LegacyMdm model(guided_step_config(state));
    model->eval();
    const int64_t batch = state.range(1);
    const torch::Tensor x = torch::randn({batch, 263, 1, 120}), t = torch::full({batch}, 500, torch::kInt64),
                        text = torch::randn({batch, 512});
    for (auto _ : state) {
        const torch::Tensor both =
            model->forward(torch::cat({x, x}), torch::cat({t, t}), torch::cat({text, torch::zeros_like(text)}));
        benchmark::DoNotOptimize(
            (both.narrow(0, batch, batch) + 2.5 * (both.narrow(0, 0, batch) - both.narrow(0, batch, batch)))
                .data_ptr());
    }
    state.counters["motions/s per step"] =
        benchmark::Counter(static_cast<double>(state.iterations() * batch), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_MdmGuidedStepLegacy)
    ->Args({512, 1})
    ->Args({512, 16})
    ->Args({256, 1})
    ->Args({256, 16})
    ->Unit(benchmark::kMillisecond);

static void BM_MdmGuidedStep(benchmark::State& state) {
    torch::NoGradGuard no_grad;
    Mdm model(guided_step_config(state));
    model->eval();
    const int64_t batch = state.range(1);
    const torch::Tensor x = torch::randn({batch, 263, 1, 120}), t = torch::full({batch}, 500, torch::kInt64),
                        text = torch::randn({batch, 512});
    for (auto _ : state) benchmark::DoNotOptimize(model->forward_guided(x, t, text, 2.5).data_ptr());
    state.counters["motions/s per step"] =
        benchmark::Counter(static_cast<double>(state.iterations() * batch), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_MdmGuidedStep)
    ->Args({512, 1})
    ->Args({512, 16})
    ->Args({256, 1})
    ->Args({256, 16})
    ->Unit(benchmark::kMillisecond);
