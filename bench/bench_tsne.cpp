// Barnes-Hut t-SNE on 5,000 points of 22 features in 5 Gaussian clusters (a catch22 table's size), 1000
// iterations: the whole embedding, one thread.
#include <benchmark/benchmark.h>

#include <random>

#include "analysis/tsne.hpp"

using namespace t2imu;

static void BM_TsneBarnesHut5000(benchmark::State& state) {
    std::mt19937_64 rng(1);
    std::normal_distribution<double> n;
    PointMatrix x(5000, 22);
    for (Eigen::Index i = 0; i < x.rows(); ++i)
        for (Eigen::Index d = 0; d < x.cols(); ++d) x(i, d) = n(rng) + 8.0 * static_cast<double>((i % 5) == d % 5);
    for (auto _ : state) benchmark::DoNotOptimize(tsne(x, {}).kl_divergence);
}
BENCHMARK(BM_TsneBarnesHut5000)->Unit(benchmark::kSecond)->Iterations(1);
