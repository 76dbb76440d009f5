// catch22 throughput: series per second at n = 40 (a 2 s IMU window at 20 Hz), 128 and 5000 samples.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "analysis/catch22.hpp"

using namespace t2imu;

// A gait-like test signal: a 2 Hz oscillation at 20 Hz sampling with seeded Gaussian noise.
static std::vector<double> gait_like(std::size_t n) {
    std::mt19937 rng(22);
    std::normal_distribution<double> noise(0.0, 0.3);
    std::vector<double> x(n);
    for (std::size_t t = 0; t < n; ++t) x[t] = 9.81 + 2.0 * std::sin(2.0 * M_PI * 2.0 * t / 20.0) + noise(rng);
    return x;
}

static void BM_Catch22(benchmark::State& state) {
    const std::vector<double> x = gait_like(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(catch22(x, false));
    state.SetItemsProcessed(state.iterations());  // items = series
}
BENCHMARK(BM_Catch22)->Arg(40)->Arg(128)->Arg(5000)->Unit(benchmark::kMicrosecond);
