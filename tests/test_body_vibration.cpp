// Body vibration (imu/body_vibration): its sd is gain x the motion's rms level, its power lies in the band, a
// motionless sensor is left unchanged (to rounding) and gain 0 to the byte, the gyroscope is never touched, draws are
// reproducible from the seed; the realism keys are validated by name and recorded.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "core/signal/fft.hpp"
#include "imu/body_vibration.hpp"
#include "imu/realism.hpp"
#include "test_util.hpp"

using namespace t2imu;
using Eigen::Vector3d;

namespace {

// 60 s at 100 Hz: a lateral sway of amplitude `amplitude` (m/s^2) at 1 Hz, gravity on y, nothing on z.
ImuSignals swaying(double amplitude) {
    ImuSignals s;
    s.rate_hz = 100;
    for (int k = 0; k < 6000; ++k) {
        const double t = k / 100.0;
        s.t.push_back(t);
        s.acc.emplace_back(amplitude * std::sin(2 * M_PI * t), -9.81, 0);
        s.gyr.emplace_back(0.1, 0, 0);
    }
    return s;
}

std::vector<double> axis_z(const ImuSignals& s) {
    std::vector<double> z;
    for (const Vector3d& a : s.acc) z.push_back(a.z());
    return z;
}

double sd(const std::vector<double>& x) {
    double mean = 0, power = 0;
    for (double v : x) mean += v / static_cast<double>(x.size());
    for (double v : x) power += (v - mean) * (v - mean) / static_cast<double>(x.size());
    return std::sqrt(power);
}

// Share of x's power (periodogram, sampled at rate) between lo and hi Hz.
double power_share(const std::vector<double>& x, double rate, double lo, double hi) {
    std::vector<std::complex<double>> c(next_power_of_two(x.size()));
    for (size_t k = 0; k < x.size(); ++k) c[k] = x[k];
    fft_in_place(c);
    double in = 0, all = 0;
    for (size_t k = 1; k <= c.size() / 2; ++k) {
        const double f = static_cast<double>(k) * rate / static_cast<double>(c.size()), p = std::norm(c[k]);
        all += p;
        if (f >= lo && f <= hi) in += p;
    }
    return in / all;
}

}  // namespace

TEST(BodyVibration, ItsSdIsTheGainTimesTheMotionsRmsLevelAndItsPowerLiesInTheBand) {
    ImuSignals s = swaying(2);
    BodyVibration v;
    v.gain = 0.15;
    add_body_vibration(v, 3, &s);
    // A 1 Hz sine has zero mean over every 1 s window, so the level is its rms, 2 / sqrt(2), everywhere.
    const std::vector<double> z = axis_z(s);
    EXPECT_NEAR(sd(z), 0.15 * std::sqrt(2.0), 0.01 * 0.15 * std::sqrt(2.0));
    // The response falls as f^4 below 5 Hz and above 12 Hz: 2.5-24 Hz holds all but ~1 % of the power.
    EXPECT_GT(power_share(z, 100, 2.5, 24), 0.98);
    EXPECT_GT(power_share(z, 100, 5, 12), 0.6);
    for (const Vector3d& g : s.gyr) EXPECT_EQ(g, Vector3d(0.1, 0, 0));
}

TEST(BodyVibration, AMotionlessSensorAndGainZeroAreLeftUnchanged) {
    ImuSignals still = swaying(0);
    const ImuSignals before = still;
    BodyVibration v;
    v.gain = 1;
    add_body_vibration(v, 3, &still);
    for (size_t k = 0; k < still.acc.size(); ++k)
        EXPECT_LT((still.acc[k] - before.acc[k]).norm(), 1e-12);  // the level's rounding
    ImuSignals moving = swaying(2);
    const ImuSignals unchanged = moving;
    add_body_vibration(BodyVibration(), 3, &moving);
    EXPECT_EQ(moving.acc, unchanged.acc);
}

TEST(BodyVibration, DrawsAreReproducibleFromTheSeed) {
    BodyVibration v;
    v.gain = 0.2;
    ImuSignals a = swaying(1), b = swaying(1), c = swaying(1);
    add_body_vibration(v, 11, &a);
    add_body_vibration(v, 11, &b);
    add_body_vibration(v, 12, &c);
    EXPECT_EQ(a.acc, b.acc);
    EXPECT_NE(a.acc, c.acc);
}

TEST(BodyVibration, RealismKeysAreValidatedAndRecorded) {
    const RealismModel m = parse_realism_toml(
        "base = \"sisfall\"\nvibration_gain = 0.15\nvibration_low_hz = 4\nvibration_high_hz = 10\n", "r.toml");
    EXPECT_DOUBLE_EQ(m.to_json()["vibration_gain"].get<double>(), 0.15);
    EXPECT_DOUBLE_EQ(m.to_json()["vibration_low_hz"].get<double>(), 4);
    EXPECT_DOUBLE_EQ(m.to_json()["vibration_high_hz"].get<double>(), 10);
    EXPECT_EQ(realism_preset("sisfall").vibration.gain, 0);
    EXPECT_TRUE(test::contains(test::error_message([] { parse_realism_toml("vibration_gain = 1.5\n", "r.toml"); }),
                               "r.toml: vibration_gain"));
    EXPECT_TRUE(test::contains(test::error_message([] { parse_realism_toml("vibration_low_hz = 0\n", "r.toml"); }),
                               "r.toml: vibration_low_hz"));
    EXPECT_TRUE(test::contains(
        test::error_message([] { parse_realism_toml("vibration_low_hz = 8\nvibration_high_hz = 6\n", "r.toml"); }),
        "r.toml: vibration_high_hz"));
}
