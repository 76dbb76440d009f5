// One MDM denoiser evaluation with classifier-free guidance (the batched conditional + unconditional pass of
// every sampling step), 120 frames, for the official size (8 layers x 512) and the default training size
// (4 x 256), at batch 1 and 16; libtorch CPU with the benchmark's thread count (see bench/README.md).
#include <benchmark/benchmark.h>

#include "diffusion/mdm.hpp"

using namespace t2imu;

static void BM_MdmGuidedStep(benchmark::State& state) {
    torch::NoGradGuard no_grad;
    MdmConfig c;
    c.latent_dim = state.range(0);
    c.num_layers = state.range(0) == 512 ? 8 : 4;
    c.ff_size = state.range(0) == 512 ? 1024 : 512;
    Mdm model(c);
    model->eval();
    const int64_t batch = state.range(1);
    const torch::Tensor x = torch::randn({batch, 263, 1, 120}), t = torch::full({batch}, 500, torch::kInt64), text = torch::randn({batch, 512});
    for (auto _ : state) benchmark::DoNotOptimize(model->forward_guided(x, t, text, 2.5).data_ptr());
    state.counters["motions/s per step"] = benchmark::Counter(static_cast<double>(state.iterations() * batch), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_MdmGuidedStep)->Args({512, 1})->Args({512, 16})->Args({256, 1})->Args({256, 16})->Unit(benchmark::kMillisecond);
