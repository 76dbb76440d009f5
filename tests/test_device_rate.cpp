// The device's own sample rate (imu/device_rate): resampling keeps what lies in the band, and a virtual sensor
// sampled at UMAFall's 20 Hz folds a 14 Hz bounce to 6 Hz, where one sampled at the output rate keeps it at 14 Hz.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "body/procedural_body.hpp"
#include "imu/device_rate.hpp"
#include "imu/virtual_imu.hpp"
#include "test_util.hpp"

using namespace t2imu;
using Eigen::Vector3d;

namespace {

// Amplitude of the `hz` component of x (sampled at rate) over samples [from, to): a one-bin DFT of a whole
// number of periods.
double amplitude_at(const std::vector<double>& x, double rate, double hz, size_t from, size_t to) {
    std::complex<double> sum = 0;
    for (size_t k = from; k < to; ++k)
        sum += x[k] * std::exp(std::complex<double>(0, -2 * M_PI * hz * static_cast<double>(k) / rate));
    return 2 * std::abs(sum) / static_cast<double>(to - from);
}

// A waist board (SisFall's: y down) on an average man bouncing 1 mm at 14 Hz, captured at 200 fps, 3 s.
std::vector<double> bouncing_vertical(double device_rate_hz) {
    const BodySpec& spec = paper_bodies()[2];
    const ProceduralBody body(spec);
    const double fps = 200;
    JointSequence seq(601, smpl22::kNumJoints, fps);
    for (int f = 0; f < 601; ++f)
        for (int j = 0; j < smpl22::kNumJoints; ++j)
            seq.at(f, j) =
                body.rest_joints()[static_cast<size_t>(j)] + Vector3d(0, 0.001 * std::sin(2 * M_PI * 14 * f / fps), 0);
    VirtualImuOptions o;
    o.rate_hz = 50;
    RealismModel m;
    m.sensor_sample_rate_hz = device_rate_hz;
    o.set_realism(m);
    const BodyImu imu = synthesize_body_imu(seq, spec, parse_sensor_sets("sisfall"), o);
    std::vector<double> y;
    for (const Vector3d& a : imu.signals[0].acc) y.push_back(a.y());
    return y;
}

}  // namespace

TEST(DeviceRate, ResamplingKeepsWhatLiesInTheBand) {
    ImuSignals s;
    s.rate_hz = 20;
    for (int k = 0; k <= 200; ++k) {
        const double t = k / 20.0;
        s.t.push_back(t);
        s.acc.emplace_back(std::sin(2 * M_PI * 3 * t), -9.81, 0.5 * t);
        s.gyr.emplace_back(0, 0, std::cos(2 * M_PI * 2 * t));
    }
    const ImuSignals r = resample_imu_signals(s, 50);
    ASSERT_EQ(r.t.size(), 501u);  // 10 s at 50 Hz, ending at the last input instant
    EXPECT_DOUBLE_EQ(r.rate_hz, 50);
    double worst = 0;
    for (size_t k = 0; k < r.t.size(); ++k) {
        const double t = static_cast<double>(k) / 50;
        EXPECT_DOUBLE_EQ(r.t[k], t);
        worst = std::max({worst, std::fabs(r.acc[k].y() + 9.81),
                          std::fabs(r.acc[k].z() - 0.5 * t)});  // offset and trend: exact up to the filter's DC gain
        if (t > 1 && t < 9)
            worst = std::max({worst, std::fabs(r.acc[k].x() - std::sin(2 * M_PI * 3 * t)),
                              std::fabs(r.gyr[k].z() - std::cos(2 * M_PI * 2 * t))});
    }
    // The Kaiser (beta 5) filter's passband ripple at 0.3 of the device's Nyquist frequency is below 1e-2.
    EXPECT_LT(worst, 1e-2);
    const ImuSignals same = resample_imu_signals(s, 20);
    EXPECT_EQ(same.acc, s.acc);
    s.rate_hz = 20.5;
    EXPECT_TRUE(test::contains(test::error_message([&] { resample_imu_signals(s, 50); }),
                               "--rate: rate: expected whole numbers of Hz"));
}

TEST(DeviceRate, ABounceAboveHalfTheDeviceRateFoldsIntoTheBand) {
    const double amplitude = 0.001 * std::pow(2 * M_PI * 14, 2);  // 7.74 m/s^2
    const std::vector<double> at_output_rate = bouncing_vertical(0), at_device_rate = bouncing_vertical(20);
    ASSERT_EQ(at_output_rate.size(), at_device_rate.size());
    // Two whole seconds inside the clip: 14 and 6 Hz both make whole periods.
    const size_t from = 25, to = 125;
    EXPECT_NEAR(amplitude_at(at_output_rate, 50, 14, from, to), amplitude, 0.05 * amplitude);
    EXPECT_LT(amplitude_at(at_output_rate, 50, 6, from, to), 0.02 * amplitude);
    EXPECT_NEAR(amplitude_at(at_device_rate, 50, 6, from, to), amplitude, 0.05 * amplitude);
    EXPECT_LT(amplitude_at(at_device_rate, 50, 14, from, to), 0.02 * amplitude);
}

TEST(DeviceRate, RealismKeyIsValidatedAndRecorded) {
    EXPECT_DOUBLE_EQ(parse_realism_toml("base = \"umafall\"\nsensor_rate_hz = 20\n", "r.toml")
                         .to_json()["sensor_rate_hz"]
                         .get<double>(),
                     20);
    EXPECT_TRUE(test::contains(test::error_message([] { parse_realism_toml("sensor_rate_hz = 2\n", "r.toml"); }),
                               "r.toml: sensor_rate_hz"));
    EXPECT_TRUE(test::contains(test::error_message([] { parse_realism_toml("sensor_rate_hz = 20.5\n", "r.toml"); }),
                               "r.toml: sensor_rate_hz: expected 0 (off) or 5 to 2000 Hz, whole"));
    VirtualImuOptions o;
    o.rate_hz = 52.5;
    RealismModel m;
    m.sensor_sample_rate_hz = 20;
    o.set_realism(m);
    EXPECT_TRUE(
        test::contains(test::error_message([&] { o.validate(); }), "--rate: rate: expected a whole number of Hz"));
}
