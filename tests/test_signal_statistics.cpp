// Signal statistics (analysis/signal_statistics) on recordings with known answers: sinusoids of set amplitude
// and frequency on a tilted gravity vector.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/signal_statistics.hpp"
#include "core/error.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

// 30 s at 50 Hz: x sways at fx with amplitude ax, y carries gravity tilted by tilt_deg towards z and a bounce.
ImuRecording recording(const std::string& activity, double fx, double ax, double tilt_deg, double fy = 1.8,
                       double ay = 1.0) {
    ImuRecording r;
    r.dataset = "t2imu", r.activity = activity, r.position = "waist", r.rate_hz = 50, r.path = activity + ".csv";
    const double g = 9.81, tilt = tilt_deg * M_PI / 180;
    for (int i = 0; i < 1500; ++i) {
        const double t = i / 50.0;
        r.t.push_back(t);
        r.samples.push_back({ax * std::sin(2 * M_PI * fx * t), -g * std::cos(tilt) + ay * std::sin(2 * M_PI * fy * t),
                             -g * std::sin(tilt), 0, 0, 0});
    }
    return r;
}

}  // namespace

TEST(SignalStatistics, SinusoidsGiveTheirLevelFrequencyAndTilt) {
    const auto s = recording_signal_statistics(recording("walking", 0.9, 2.0, 16), 20);
    EXPECT_NEAR(s.at("sd_x"), 2.0 / std::sqrt(2), 0.02);
    EXPECT_NEAR(s.at("sd_y"), 1.0 / std::sqrt(2), 0.02);
    EXPECT_NEAR(s.at("sd_z"), 0, 1e-3);  // a constant, but for the resampling filter's edges
    EXPECT_NEAR(s.at("dom_x_hz"), 0.9, 0.02);
    EXPECT_NEAR(s.at("dom_y_hz"), 1.8, 0.02);
    EXPECT_NEAR(s.at("gravity_tilt_deg"), 16, 0.1);
    EXPECT_NEAR(s.at("mean_z"), -9.81 * std::sin(16 * M_PI / 180), 0.01);
    EXPECT_LT(s.at("hf_share"), 0.01);  // nothing above 3 Hz
    EXPECT_LT(s.at("hf_sd_x"), 0.05);
    const auto fast = recording_signal_statistics(recording("running", 5.0, 2.0, 0, 5.0), 20);
    EXPECT_GT(fast.at("hf_share"), 0.99);
    EXPECT_NEAR(fast.at("hf_sd_x"), 2.0 / std::sqrt(2), 0.03);  // the whole 5 Hz sway
    EXPECT_NEAR(fast.at("hf_sd_y"), 1.0 / std::sqrt(2), 0.03);
    EXPECT_NEAR(fast.at("dom_x_hz"), 5.0, 0.02);
    // d|a|/dt of a 5 Hz bounce of 1 m/s^2 on g: rms 2 pi 5 / sqrt(2) (first differences at 20 Hz lose some).
    EXPECT_GT(fast.at("jerk_rms"), 10);
    EXPECT_LT(fast.at("jerk_rms"), 2 * M_PI * 5 / std::sqrt(2) * 1.1);
}

// Standing still with one 1 s push up (|a| 2 m/s^2 above g) and, later, one 1 s drop (1 m/s^2 below): the swings.
TEST(SignalStatistics, TheSwingsOfATransitionAreItsRiseAndDipAboveAndBelowTheMedian) {
    ImuRecording r;
    r.dataset = "t2imu", r.activity = "sitting", r.position = "waist", r.rate_hz = 50, r.path = "sitting.csv";
    for (int i = 0; i < 600; ++i) {
        const double t = i / 50.0, push = t >= 4 && t < 5 ? 2.0 : t >= 8 && t < 9 ? -1.0 : 0.0;
        r.t.push_back(t);
        r.samples.push_back({0, -(9.81 + push), 0, 0, 0, 0});
    }
    const auto s = recording_signal_statistics(r, 20);
    EXPECT_NEAR(s.at("mag_p50"), 9.81, 1e-3);
    EXPECT_NEAR(s.at("mag_rise"), 2.0, 0.05);
    EXPECT_NEAR(s.at("mag_dip"), 1.0, 0.05);
    // A 5 Hz bounce of 1 m/s^2 averages out over 0.2 s: steps are not swings.
    const auto bounce = recording_signal_statistics(recording("running", 5.0, 0.0, 0, 5.0), 20);
    EXPECT_LT(bounce.at("mag_rise"), 0.1);
}

TEST(SignalStatistics, ComparesActivitiesBothSetsHoldWithRatios) {
    const std::vector<ImuRecording> real = {recording("walking", 0.9, 2.0, 16), recording("lying", 0.5, 0.1, 80)};
    const std::vector<ImuRecording> synthetic = {recording("walking", 0.9, 1.0, 4), recording("walking", 0.9, 1.0, 4)};
    const SignalStatisticsComparison c = compare_signal_statistics(real, synthetic, {"waist", 20});
    ASSERT_EQ(c.size(), 1u);  // only walking is in both
    EXPECT_EQ(c.at("walking").synthetic_recordings, 2);
    EXPECT_NEAR(c.at("walking").statistics.at("sd_x").ratio, 0.5, 0.01);
    EXPECT_NEAR(c.at("walking").statistics.at("gravity_tilt_deg").real, 16, 0.1);
    // The result file reads back as written, to the byte; a broken field is refused by its dotted key.
    const nlohmann::json doc = signal_statistics_comparison_json(c);
    EXPECT_EQ(doc["walking"]["recordings"]["synthetic"], 2);
    EXPECT_EQ(signal_statistics_comparison_json(parse_signal_statistics_comparison(doc, "s.json")).dump(2),
              doc.dump(2));
    nlohmann::json broken = doc;
    broken["walking"]["sd_x"]["ratio"] = "half";
    EXPECT_EQ(test::error_message([&] { parse_signal_statistics_comparison(broken, "s.json"); }),
              "s.json: walking.sd_x.ratio: expected a number (got \"half\")");
    EXPECT_THROW(compare_signal_statistics(real, synthetic, {"wrist", 20}),
                 Error);  // a position neither holds: refused, not {}
    ImuRecording short_one = recording("walking", 0.9, 1.0, 0);
    short_one.samples.resize(60);
    short_one.t.resize(60);
    EXPECT_THROW(recording_signal_statistics(short_one, 20), Error);
    for (double rate : {7.9, 1001.0, std::nan("")}) {  // refused before any work, naming the option
        try {
            activity_signal_statistics(real, {"waist", rate});
            ADD_FAILURE() << rate;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("--rate"), std::string::npos) << e.what();
        }
    }
}

namespace {

// 30 s at 50 Hz of a board (y down) rolling about its z axis by roll_amp sin(2 pi f t) while its lateral axis x
// also accelerates by sway sin(2 pi f t + phase): the roll puts -g sin(roll) on x, and the gyroscope reads it.
// It also turns about the vertical at f (a walker's pelvis yawing once a stride), 0.3 rad/s.
ImuRecording rolling_board(double f, double roll_amp, double sway, double phase) {
    ImuRecording r;
    r.dataset = "t2imu", r.activity = "walking", r.position = "waist", r.rate_hz = 50, r.path = "rolling.csv";
    const double g = 9.81;
    for (int i = 0; i < 1500; ++i) {
        const double t = i / 50.0, w = 2 * M_PI * f, roll = roll_amp * std::sin(w * t);
        r.t.push_back(t);
        r.samples.push_back({-g * std::sin(roll) + sway * std::sin(w * t + phase), -g * std::cos(roll), 0, 0,
                             -0.3 * std::sin(w * t), roll_amp * w * std::cos(w * t)});
    }
    return r;
}

}  // namespace

TEST(SignalStatistics, GravityRatioSeparatesTheRollFromTheSway) {
    // G / K = (i g A) / (B e^{i phase} (-i)) = -g A e^{-i phase} / B: against the sway (phase 0) it is -gA/B,
    // with it (phase pi) +gA/B, in quadrature (phase pi/2) i gA/B. g A / B = 9.81 x 0.05 / 1 = 0.49.
    const double ratio = 9.81 * 0.05 / 1.0;
    const struct { double phase, re, im; } cases[] = {{0, -ratio, 0}, {M_PI, ratio, 0}, {M_PI / 2, 0, ratio}};
    for (const auto& c : cases) {
        const auto s = recording_signal_statistics(rolling_board(0.9, 0.05, 1.0, c.phase), 20);
        EXPECT_NEAR(s.at("yaw_hz"), 0.9, 0.02) << c.phase;
        EXPECT_NEAR(s.at("grav_x_re"), c.re, 0.02) << c.phase;
        EXPECT_NEAR(s.at("grav_x_im"), c.im, 0.02) << c.phase;
    }
    // The roll rate (gyro z) is 0.05 x 2 pi 0.9 = 0.283 rad/s at 0.9 Hz: sd 0.2; the yaw rate (y) 0.3 / sqrt(2).
    const auto board = recording_signal_statistics(rolling_board(0.9, 0.05, 1.0, 0), 20);
    EXPECT_NEAR(board.at("gyr_sway_sd_z"), 0.05 * 2 * M_PI * 0.9 / std::sqrt(2), 0.005);
    EXPECT_NEAR(board.at("gyr_sway_sd_y"), 0.3 / std::sqrt(2), 0.005);
    EXPECT_EQ(board.at("gyr_sway_sd_x"), 0);
    const auto quick = recording_signal_statistics(rolling_board(4.0, 0.05, 1.0, 0), 20);  // above the sway band
    EXPECT_LT(quick.at("gyr_sway_sd_y"), 0.01);
    // Without a gyroscope there is no gravity part to separate.
    const auto still = recording_signal_statistics(recording("walking", 0.9, 2.0, 16), 20);
    EXPECT_EQ(still.at("yaw_hz"), 0);
    EXPECT_EQ(still.at("grav_x_re"), 0);
    EXPECT_EQ(still.at("grav_x_im"), 0);
    EXPECT_EQ(still.at("gyr_sway_sd_y"), 0);
}
