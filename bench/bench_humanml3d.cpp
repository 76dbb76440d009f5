// HumanML3D conversions on a 196-frame motion (the 20 fps example walk, imported and tiled to 196 frames).
// Reports frames per second.
#include <benchmark/benchmark.h>

#include "motion/humanml3d.hpp"
#include "motion/mocap_import.hpp"

using namespace t2imu;

static JointSequence example_motion_196() {
    const JointSequence walk = import_motion(std::string(T2IMU_SOURCE_DIR) + "/examples/cmu_07_05_slow_walk.bvh");
    JointSequence s(196, 22, 20.0);
    for (int f = 0; f < 196; ++f)
        for (int j = 0; j < 22; ++j) s.at(f, j) = walk.at(f % walk.num_frames, j);
    return s;
}

static void BM_JointsToFeatures(benchmark::State& state) {
    const JointSequence s = example_motion_196();
    for (auto _ : state) benchmark::DoNotOptimize(joints_to_features(s));
    state.SetItemsProcessed(state.iterations() * s.num_frames);
    state.counters["frames/s"] =
        benchmark::Counter(static_cast<double>(state.iterations() * s.num_frames), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_JointsToFeatures)->Unit(benchmark::kMillisecond);

static void BM_RecoverFromRic(benchmark::State& state) {
    const FeatureMatrix f = joints_to_features(example_motion_196());
    for (auto _ : state) benchmark::DoNotOptimize(recover_from_ric(f));
    state.counters["frames/s"] =
        benchmark::Counter(static_cast<double>(state.iterations() * f.rows()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RecoverFromRic)->Unit(benchmark::kMicrosecond);
