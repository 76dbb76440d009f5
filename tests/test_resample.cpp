// resample_poses: a constant-rate rotation and translation resampled 30 -> 20 fps land on the exact angles and
// positions in between; a 120 -> 20 fps decimation with a rounded frame time keeps source frames exactly (and
// the last one); the same rate is the identity; empty input and bad rates are refused.
// resample_joints: exact at shared instants, exact on a parabola between (Catmull-Rom), up and down in rate.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/error.hpp"
#include "motion/resample.hpp"

using namespace t2imu;
using Eigen::Vector3d;

namespace {
// One joint turning about Y by `rad_per_frame` and moving along X by `m_per_frame`; a second joint fixed.
std::vector<BvhPose> turning(int frames, double rad_per_frame, double m_per_frame) {
    std::vector<BvhPose> poses;
    for (int f = 0; f < frames; ++f) {
        BvhPose p;
        p.rotation = {Quat(Eigen::AngleAxisd(rad_per_frame * f, Vector3d::UnitY())), Quat::Identity()};
        p.translation = {Vector3d(m_per_frame * f, 1.0, 0), Vector3d(0, 0.5, 0)};
        poses.push_back(p);
    }
    return poses;
}

double angle_about_y(const Quat& q) {
    const Eigen::AngleAxisd aa(q);
    return aa.angle() * aa.axis().dot(Vector3d::UnitY());
}
}  // namespace

TEST(Resample, ThirtyToTwentyFpsInterpolatesOnTheSourcePath) {
    // 31 frames at 30 fps span 1 s: 21 frames at 20 fps. Output frame k is at source position 1.5 k, so its
    // angle is 0.1 x 1.5 k rad (slerp about a fixed axis is linear in angle) and its x is 0.05 x 1.5 k m.
    const std::vector<BvhPose> out = resample_poses(turning(31, 0.1, 0.05), 1.0 / 30, 20);
    ASSERT_EQ(out.size(), 21u);
    for (size_t k = 0; k < out.size(); ++k) {
        EXPECT_NEAR(angle_about_y(out[k].rotation[0]), 0.15 * k, 1e-12) << k;
        EXPECT_NEAR(out[k].translation[0].x(), 0.075 * k, 1e-12) << k;
        EXPECT_NEAR(out[k].translation[0].y(), 1.0, 1e-15);
        EXPECT_NEAR(out[k].rotation[1].angularDistance(Quat::Identity()), 0.0, 1e-12);
    }
}

TEST(Resample, ExactDecimationKeepsSourceFramesDespiteARoundedFrameTime) {
    // 121 frames at 120 fps, the frame time printed as 0.00833333: every sixth frame, exactly, and the last.
    const std::vector<BvhPose> src = turning(121, 0.01, 0.001);
    const std::vector<BvhPose> out = resample_poses(src, 0.00833333, 20);
    ASSERT_EQ(out.size(), 21u);
    for (size_t k = 0; k < out.size(); ++k) {
        EXPECT_EQ(out[k].translation[0], src[6 * k].translation[0]) << k;
        EXPECT_EQ(out[k].rotation[0].coeffs(), src[6 * k].rotation[0].coeffs()) << k;
    }
}

TEST(Resample, SameRateIsTheIdentityAndOneFrameStaysOne) {
    const std::vector<BvhPose> src = turning(10, 0.2, 0.1);
    const std::vector<BvhPose> out = resample_poses(src, 0.05, 20);
    ASSERT_EQ(out.size(), src.size());
    for (size_t k = 0; k < src.size(); ++k) EXPECT_EQ(out[k].translation[0], src[k].translation[0]);
    EXPECT_EQ(resample_poses(turning(1, 0, 0), 0.01, 20).size(), 1u);
    // Upsampling 10 -> 20 fps doubles the frames less one, the midpoints halfway.
    const std::vector<BvhPose> up = resample_poses(src, 0.1, 20);
    ASSERT_EQ(up.size(), 19u);
    EXPECT_NEAR(angle_about_y(up[3].rotation[0]), 0.3, 1e-12);
    EXPECT_NEAR(up[3].translation[0].x(), 0.15, 1e-12);
}

TEST(Resample, RefusesEmptyInputAndBadRates) {
    auto message = [](auto f) {
        try {
            f();
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message([] { resample_poses({}, 0.01, 20); }).find("frames"), std::string::npos);
    EXPECT_NE(message([] { resample_poses(turning(3, 0.1, 0), 0.01, 0); }).find("rate"), std::string::npos);
    EXPECT_NE(message([] { resample_poses(turning(3, 0.1, 0), -0.01, 20); }).find("rate"), std::string::npos);
    EXPECT_NE(message([] { resample_poses(turning(3, 0.1, 0), 0.01, NAN); }).find("rate"), std::string::npos);
}

namespace {
// Two joints: one on the parabola x = t^2 / 2, y = 1 - 3 t (m, t in s), one fixed.
JointSequence parabola(int frames, double fps) {
    JointSequence m(frames, 2, fps);
    for (int f = 0; f < frames; ++f) {
        const double t = f / fps;
        m.at(f, 0) = Vector3d(0.5 * t * t, 1 - 3 * t, 0);
        m.at(f, 1) = Vector3d(0.2, 0.3, 0.4);
    }
    return m;
}
}  // namespace

TEST(Resample, JointPositionsAreExactAtSharedInstantsAndOnAParabolaBetween) {
    const JointSequence m = parabola(31, 30);  // 1 s
    const JointSequence r = resample_joints(m, 20);
    ASSERT_EQ(r.num_frames, 21);
    EXPECT_DOUBLE_EQ(r.fps, 20);
    for (int k = 0; k < r.num_frames; ++k) {
        const double t = k / 20.0;
        if (k % 2 == 0) {
            EXPECT_EQ(r.at(k, 0), m.at(3 * k / 2, 0)) << k;  // a source frame: taken as it is
        }
        // Catmull-Rom reproduces a quadratic exactly away from the ends (where the end frame repeats).
        if (t > 1 / 30.0 && t < 1 - 1 / 30.0) {
            EXPECT_NEAR((r.at(k, 0) - Vector3d(0.5 * t * t, 1 - 3 * t, 0)).norm(), 0, 1e-12) << k;
        }
        EXPECT_EQ(r.at(k, 1), Vector3d(0.2, 0.3, 0.4));
    }
    // Upward: 20 -> 60 fps keeps the span, three frames per source frame.
    const JointSequence up = resample_joints(parabola(21, 20), 60);
    EXPECT_EQ(up.num_frames, 61);
    EXPECT_NEAR(up.at(31, 0).x(), 0.5 * std::pow(31 / 60.0, 2), 1e-12);
    EXPECT_THROW(resample_joints(m, 0), Error);
}
