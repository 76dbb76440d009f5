// Bodies and virtual IMUs on a 10 s clip (the 20 fps example walk, imported and tiled to 201 frames): fitting
// frames/s, IMU synthesis samples/s, and the whole stage for 8 bodies x 7 sensors. One thread.
#include <benchmark/benchmark.h>

#include "body/fitting.hpp"
#include "body/procedural_body.hpp"
#include "imu/virtual_imu.hpp"
#include "motion/mocap_import.hpp"

using namespace t2imu;

static JointSequence example_clip_10s() {
    const JointSequence walk = import_motion(std::string(T2IMU_SOURCE_DIR) + "/examples/cmu_07_05_slow_walk.bvh");
    JointSequence s(201, 22, 20.0);
    for (int f = 0; f < 201; ++f)
        for (int j = 0; j < 22; ++j) s.at(f, j) = walk.at(f % walk.num_frames, j);
    return s;
}

static void BM_FitBody(benchmark::State& state) {
    const JointSequence clip = example_clip_10s();
    const ProceduralBody body(paper_bodies()[2]);
    for (auto _ : state) benchmark::DoNotOptimize(fit_body(clip, body));
    state.counters["frames/s"] =
        benchmark::Counter(static_cast<double>(state.iterations() * clip.num_frames), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FitBody)->Unit(benchmark::kMicrosecond);

static void BM_SynthesizeImu(benchmark::State& state) {
    const JointSequence clip = example_clip_10s();
    const ProceduralBody body(paper_bodies()[2]);
    const FittedMotion fitted = fit_body(clip, body);
    const SensorMount mount = mount_sensor(body, builtin_placement_set("realworld").sensors[3]);
    std::vector<Eigen::Vector3d> p;
    std::vector<Quat> q;
    sensor_track(body, fitted, mount, &p, &q);
    size_t samples = 0;
    for (auto _ : state) {
        const ImuSignals s = synthesize_imu(p, q, clip.fps, 50.0);
        samples += s.t.size();
        benchmark::DoNotOptimize(s.acc.data());
    }
    state.counters["samples/s"] = benchmark::Counter(static_cast<double>(samples), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SynthesizeImu)->Unit(benchmark::kMicrosecond);

// What `t2imu imu synth --body paper8 --sensors realworld --rate 50` computes for one 10 s clip (without writing).
static void BM_Clip10sPaper8Realworld(benchmark::State& state) {
    const JointSequence clip = example_clip_10s();
    const std::vector<SensorPlacement> sensors = parse_sensor_sets("realworld");
    VirtualImuOptions options;
    options.rate_hz = 50;
    for (auto _ : state)
        for (const BodySpec& b : paper_bodies())
            benchmark::DoNotOptimize(synthesize_body_imu(clip, b, sensors, options));
}
BENCHMARK(BM_Clip10sPaper8Realworld)->Unit(benchmark::kMillisecond);
