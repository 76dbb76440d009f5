// The trunk-sway lever (body/trunk_sway): a pelvis turning slowly and swaying about its three axes keeps its
// heading and its roll, while its pitch and yaw sway shrink by the gain plus what the slow part passes; limbs,
// joint positions and gains of 1 are left alone.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "body/trunk_sway.hpp"
#include "motion/quaternion.hpp"
#include "motion/skeleton.hpp"

using namespace t2imu;
using Eigen::AngleAxisd;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

constexpr double kSwayFps = 50;

Matrix3d heading_at(double t) { return AngleAxisd(0.7 + 0.3 * t, Vector3d::UnitY()).toRotationMatrix(); }

// The sway in the pelvis's rest axes (X left: pitch, Y up: yaw, Z front: roll), rad, at t seconds.
Vector3d sway_at(double t) {
    return {0.05 * std::sin(2 * M_PI * 2 * t), 0.10 * std::sin(2 * M_PI * 1 * t),
            0.08 * std::sin(2 * M_PI * 1 * t + 1)};
}

// 10 s of a walker turning at 0.3 rad/s, the pelvis swaying about a heading; limbs rotated arbitrarily.
std::vector<PosedFrame> swaying_walker() {
    std::vector<PosedFrame> frames(500);
    for (size_t f = 0; f < frames.size(); ++f) {
        const double t = static_cast<double>(f) / kSwayFps;
        const Vector3d v = sway_at(t);
        for (int j = 0; j < smpl22::kNumJoints; ++j) {
            frames[f].joints[static_cast<size_t>(j)] = Vector3d(0.1 * j, 1 + 0.01 * t, t);
            frames[f].rotation[static_cast<size_t>(j)] = AngleAxisd(0.02 * j * t, Vector3d::UnitX()).toRotationMatrix();
        }
        frames[f].rotation[smpl22::pelvis] = heading_at(t) * AngleAxisd(v.norm(), v.normalized()).toRotationMatrix();
    }
    return frames;
}

// Amplitude of the f-Hz sine in x[from, from + count) (whole periods).
double sway_amplitude_at(const std::vector<double>& x, double f, size_t from, size_t count) {
    double c = 0, s = 0;
    for (size_t k = from; k < from + count; ++k) {
        c += x[k] * std::cos(2 * M_PI * f * static_cast<double>(k) / kSwayFps);
        s += x[k] * std::sin(2 * M_PI * f * static_cast<double>(k) / kSwayFps);
    }
    return 2 * std::hypot(c, s) / static_cast<double>(count);
}

}  // namespace

TEST(TrunkSway, KeepsHeadingAndRollAndScalesPitchAndYawSwayByTheirGains) {
    const std::vector<PosedFrame> before = swaying_walker();
    const TrunkSway sway{0.5, 0.2, 0.5};
    std::vector<PosedFrame> after = before;
    apply_trunk_sway(sway, smpl22::pelvis, kSwayFps, &after);
    // The sway left over: the edited rotation seen from the true heading, as a rotation vector in rest axes.
    std::vector<double> pitch, yaw, roll;
    for (size_t f = 0; f < after.size(); ++f) {
        const AngleAxisd w(
            Matrix3d(heading_at(static_cast<double>(f) / kSwayFps).transpose() * after[f].rotation[smpl22::pelvis]));
        const Vector3d v = w.angle() * w.axis();
        pitch.push_back(v.x()), yaw.push_back(v.y()), roll.push_back(v.z());
    }
    // The slow part (sd 0.5 s) passes exp(-(2 pi f 0.5)^2 / 2) of an f-Hz sway: 0.0072 at 1 Hz, 2.7e-9 at 2 Hz,
    // so the device keeps gain + (1 - gain) x that. Tolerance: second-order cross terms of 0.1-rad rotations.
    const double pass1 = std::exp(-std::pow(2 * M_PI * 0.5, 2) / 2);
    EXPECT_NEAR(sway_amplitude_at(pitch, 2, 100, 300), 0.05 * 0.5, 1e-3);
    EXPECT_NEAR(sway_amplitude_at(yaw, 1, 100, 300), 0.10 * (0.2 + 0.8 * pass1), 1e-3);
    EXPECT_NEAR(sway_amplitude_at(roll, 1, 100, 300), 0.08, 1e-3);
    double mean_yaw = 0;  // the heading is kept: no offset about the long axis
    for (size_t k = 100; k < 400; ++k) mean_yaw += yaw[k] / 300;
    EXPECT_NEAR(mean_yaw, 0, 1e-3);
    // Only the pelvis's rotation changes.
    for (size_t f = 0; f < after.size(); f += 25)
        for (int j = 0; j < smpl22::kNumJoints; ++j) {
            const size_t i = static_cast<size_t>(j);
            EXPECT_EQ(after[f].joints[i], before[f].joints[i]);
            if (j != smpl22::pelvis) {
                EXPECT_EQ(after[f].rotation[i], before[f].rotation[i]);
            }
        }
}

TEST(TrunkSway, LeavesLimbsAndUnitGainsAlone) {
    const std::vector<PosedFrame> before = swaying_walker();
    EXPECT_TRUE(is_trunk_segment(smpl22::spine3));
    EXPECT_FALSE(is_trunk_segment(smpl22::left_hip));
    const auto unchanged = [&](const TrunkSway& sway, int segment) {
        std::vector<PosedFrame> after = before;
        apply_trunk_sway(sway, segment, kSwayFps, &after);
        for (size_t f = 0; f < after.size(); ++f)
            for (size_t j = 0; j < smpl22::kNumJoints; ++j)
                if (after[f].rotation[j] != before[f].rotation[j]) return false;
        return true;
    };
    EXPECT_TRUE(unchanged({1, 1, 0.5}, smpl22::pelvis));
    EXPECT_TRUE(unchanged({0, 0, 0.5}, smpl22::left_hip));
    EXPECT_FALSE(unchanged({0, 0, 0.5}, smpl22::spine3));
}
