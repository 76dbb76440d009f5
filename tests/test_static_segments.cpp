// analysis/static_segments.cpp: on a recording that moves for 4 s and then lies still with known white noise
// and a known gyroscope offset, the quietest window finds the still part and reads the noise and offset back;
// over recordings the offsets' spread is their sd; a sensor model's prediction is density * sqrt(rate / 2).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analysis/static_segments.hpp"
#include "core/error.hpp"

using namespace t2imu;

namespace {

// 10 s at 50 Hz: 4 s of a 1.5 Hz swing (2 m/s^2 on x, 1 rad/s on z), then still with gravity on y, acc noise
// sd 0.02 m/s^2, gyr noise sd 0.003 rad/s and gyr offset `offset_x` rad/s on x.
ImuRecording moving_then_still(double offset_x, uint64_t seed) {
    ImuRecording r;
    r.path = "r" + std::to_string(seed) + ".csv";
    r.position = "waist";
    r.activity = "lying";
    r.rate_hz = 50;
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> acc_noise(0, 0.02), gyr_noise(0, 0.003);
    for (int k = 0; k < 500; ++k) {
        const double t = k / 50.0;
        const double swing = t < 4 ? std::sin(2 * M_PI * 1.5 * t) : 0;
        r.t.push_back(t);
        r.samples.push_back({2 * swing + acc_noise(rng), 9.80665 + acc_noise(rng), acc_noise(rng),
                             offset_x + gyr_noise(rng), gyr_noise(rng), swing + gyr_noise(rng)});
    }
    return r;
}

}  // namespace

TEST(StaticSegments, QuietestWindowReadsNoiseAndOffsetBack) {
    const nlohmann::json j = quietest_window_statistics(moving_then_still(0.01, 1), 2.0);
    EXPECT_GE(j["window_start_s"].get<double>(), 4.0);  // in the still part
    for (const char* axis : {"x", "y", "z"}) {
        EXPECT_NEAR(j[std::string("acc_sd_") + axis].get<double>(), 0.02, 0.004)
            << axis;  // 100 samples: sd within ~15 %
        EXPECT_NEAR(j[std::string("gyr_sd_") + axis].get<double>(), 0.003, 0.0006) << axis;
    }
    EXPECT_NEAR(j["gyr_mean_x"].get<double>(), 0.01, 0.001);  // the offset, to 3 standard errors
    EXPECT_NEAR(j["acc_norm_error"].get<double>(), 0.0, 0.01);
    EXPECT_THROW(quietest_window_statistics(moving_then_still(0, 2), 20.0), Error);  // shorter than one window
}

TEST(StaticSegments, SummaryOverRecordingsAndTheDevicePrediction) {
    std::vector<ImuRecording> recordings;
    const double offsets[4] = {0.01, -0.01, 0.03, -0.03};  // sd over recordings: sqrt((1 + 1 + 9 + 9) / 4) * 0.01
    for (int i = 0; i < 4; ++i) recordings.push_back(moving_then_still(offsets[i], 10 + static_cast<uint64_t>(i)));
    recordings.back().position = "wrist";
    const SensorNoiseModel sisfall = parse_noise_model("sisfall");
    const nlohmann::json all = static_segment_noise(recordings, {"", 2.0}, sisfall);
    EXPECT_EQ(all["recordings"], 4);
    EXPECT_NEAR(all["measured"]["gyr_offset_sd_x"].get<double>(), std::sqrt(5.0) * 0.01, 0.002);
    EXPECT_NEAR(all["measured"]["acc_sd_y"].get<double>(), 0.02, 0.004);
    EXPECT_NEAR(all["sensor_model"]["acc_sd"].get<double>(), sisfall.acc_noise_density * 5.0,
                1e-12);  // sqrt(50 / 2) = 5
    EXPECT_EQ(static_segment_noise(recordings, {"waist", 2.0}, parse_noise_model("none"))["recordings"], 3);
    EXPECT_FALSE(static_segment_noise(recordings, {"waist", 2.0}, parse_noise_model("none")).contains("sensor_model"));
    EXPECT_THROW(static_segment_noise(recordings, {"ankle", 2.0}, sisfall), Error);
    for (double window : {0.4, 61.0, std::nan("")}) {  // refused before any work, naming the option
        try {
            static_segment_noise(recordings, {"waist", window}, sisfall);
            ADD_FAILURE() << window;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("--window"), std::string::npos) << e.what();
        }
    }
}
