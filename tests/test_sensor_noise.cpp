// The sensor error model: white-noise level from the density, bias, saturation, quantisation, seeding.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "imu/sensor_noise.hpp"

using namespace t2imu;
using Eigen::Vector3d;

namespace {
ImuSignals constant_signals(size_t n, double rate, const Vector3d& acc, const Vector3d& gyr) {
    ImuSignals s;
    s.rate_hz = rate;
    for (size_t k = 0; k < n; ++k) {
        s.t.push_back(static_cast<double>(k) / rate);
        s.acc.push_back(acc);
        s.gyr.push_back(gyr);
    }
    return s;
}
}  // namespace

TEST(SensorNoise, WhiteNoiseHasTheDensitysStandardDeviation) {
    SensorNoiseModel m = parse_noise_model(
        "smartphone,acc_bias_sd=0,gyr_bias_sd=0,acc_bias_walk=0,gyr_bias_walk=0,scale_sd=0,misalignment_deg=0,bits=0");
    ImuSignals s = constant_signals(200000, 100, Vector3d(0, 9.81, 0), Vector3d::Zero());
    apply_sensor_noise(m, 1, &s);
    double sum = 0, sum2 = 0;
    for (const Vector3d& a : s.acc) {
        sum += a.x();
        sum2 += a.x() * a.x();
    }
    const double n = static_cast<double>(s.acc.size()), sd = std::sqrt(sum2 / n - (sum / n) * (sum / n));
    const double expected = 180e-6 * 9.80665 * std::sqrt(100.0);  // density * sqrt(rate)
    EXPECT_NEAR(sd / expected, 1.0, 0.01);
    EXPECT_NEAR(sum / n, 0.0, 5 * expected / std::sqrt(n));
}

TEST(SensorNoise, SaturatesAndQuantises) {
    SensorNoiseModel m = parse_noise_model(
        "hugadb,acc_noise_density=0,gyr_noise_density=0,acc_bias_sd=0,gyr_bias_sd=0,"
        "acc_bias_walk=0,gyr_bias_walk=0,scale_sd=0,misalignment_deg=0");
    ImuSignals s = constant_signals(10, 50, Vector3d(30, -30, 1.0), Vector3d(0.0123456, 50, 0));
    apply_sensor_noise(m, 1, &s);
    const double range = 2 * 9.80665, lsb = 2 * range / 65536;
    EXPECT_DOUBLE_EQ(s.acc[0].x(), range);
    EXPECT_DOUBLE_EQ(s.acc[0].y(), -range);
    EXPECT_NEAR(std::remainder(s.acc[0].z(), lsb), 0.0, 1e-12);
    EXPECT_LE(std::fabs(s.acc[0].z() - 1.0), lsb / 2 + 1e-15);
    EXPECT_DOUBLE_EQ(s.gyr[0].y(), 2000 * M_PI / 180);
}

TEST(SensorNoise, SeededBiasIsConstantWithoutWalkAndDiffersBetweenSeeds) {
    SensorNoiseModel m =
        parse_noise_model("smartphone,acc_noise_density=0,gyr_noise_density=0,acc_bias_walk=0,gyr_bias_walk=0,bits=0");
    ImuSignals a = constant_signals(50, 50, Vector3d(0, 9.81, 0), Vector3d::Zero()), b = a, c = a;
    apply_sensor_noise(m, 5, &a);
    apply_sensor_noise(m, 5, &b);
    apply_sensor_noise(m, 6, &c);
    EXPECT_EQ(a.acc[10], b.acc[10]);
    EXPECT_NE(a.acc[10], c.acc[10]);
    EXPECT_EQ(a.gyr[0], a.gyr[49]);  // a constant bias, no walk
    EXPECT_GT(a.gyr[0].norm(), 0.0);
}

TEST(SensorNoise, NoneChangesNothingAndBadSpecsAreRefused) {
    ImuSignals s = constant_signals(5, 50, Vector3d(1, 2, 3), Vector3d(4, 5, 6));
    apply_sensor_noise(parse_noise_model("none"), 1, &s);
    EXPECT_EQ(s.acc[2], Vector3d(1, 2, 3));
    for (const char* bad : {"loud", "none,bits=3", "smartphone,colour=2", "smartphone,bits=-1", "smartphone,bits"})
        EXPECT_THROW(parse_noise_model(bad), Error) << bad;
}
