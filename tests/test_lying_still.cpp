// Lying still on a supine pose built from HumanML3D's target skeleton, where the breathing motion is known.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/error.hpp"
#include "motion/lying_still.hpp"
#include "motion/motion_edit.hpp"
#include "motion/motion_quality.hpp"
#include "motion/skeleton.hpp"
#include "test_util.hpp"

namespace t2imu {
namespace {

using Eigen::Vector3d;
using namespace smpl22;

// A short "lie-down" clip of 5 frames: the rest pose with the forearms bent toward the belly, turned -90 deg
// about X (head toward -Z, face up), the pelvis 0.1 m above the floor; frame 0 still standing.
JointSequence lie_down() {
    JointSequence m(5, kNumJoints, kFps);
    std::array<Vector3d, kNumJoints> bones = kTargetOffsets;
    for (int wrist : {left_wrist, right_wrist}) {
        const double across = wrist == left_wrist ? -0.6 : 0.6;  // toward the midline: left is +X
        bones[static_cast<size_t>(wrist)] = bones[static_cast<size_t>(wrist)].norm() * Vector3d(across, 0, 0.8);
    }
    const Eigen::Matrix3d supine = Eigen::AngleAxisd(-test::kPi / 2, Vector3d::UnitX()).toRotationMatrix();
    for (int f = 0; f < m.num_frames; ++f) {
        m.at(f, pelvis) = Vector3d(0, f == 0 ? 0.9 : 0.1, 0);
        for (int j = 1; j < kNumJoints; ++j)
            m.at(f, j) = m.at(f, kParents[static_cast<size_t>(j)]) +
                         (f == 0 ? Eigen::Matrix3d::Identity() : supine) * bones[static_cast<size_t>(j)];
    }
    return m;
}

TEST(LyingStill, HoldsTheLastPoseAndBreathesWithTheChestOnly) {
    const JointSequence src = lie_down();
    LyingOptions o;
    const JointSequence m = lying_still(src, o);
    ASSERT_EQ(m.num_frames, 201);  // 10 s at 20 fps
    EXPECT_LT(max_bone_length_error(m, bone_lengths(src, 4)), 1e-9);
    for (int f = 0; f < m.num_frames; ++f)
        for (int j : {pelvis, left_hip, right_knee, left_ankle, right_foot, spine1, spine2, left_wrist, right_wrist})
            EXPECT_NEAR((m.at(f, j) - src.at(4, j)).norm(), 0.0, 1e-12) << kJointNames[static_cast<size_t>(j)];
    // Supine, the head turns up about spine2 by chest_rad at mid-breath: it rises by r sin(0.02), r its
    // distance from spine2 along the body (the skeleton's head sits forward of the neck: that part turns away).
    const Vector3d r = src.at(4, head) - src.at(4, spine2);
    const double half_breath = 60.0 / o.breaths_per_min / 2 * kFps;  // frames
    const int mid = static_cast<int>(std::lround(half_breath));
    // Turning about the body's left (+X, unchanged by the turn to supine) takes its up (-Z) toward its front (+Y).
    const Vector3d turned =
        Eigen::AngleAxisd(0.02 * 0.5 * (1 - std::cos(2 * test::kPi * mid / (2 * half_breath))), Vector3d::UnitX()) * r;
    EXPECT_NEAR(m.at(mid, head).y() - src.at(4, head).y(), turned.y() - r.y(), 1e-12);
    EXPECT_GT(m.at(mid, head).y() - src.at(4, head).y(), 0.005);
    EXPECT_NEAR(m.at(0, head).y(), src.at(4, head).y(), 1e-12);  // starts at the end of an exhale
    EXPECT_TRUE(quality_failures(score_motion(m), default_quality_thresholds()).empty());
}

TEST(LyingStill, ProneTheBreathingLiftsAndNeverSinks) {
    JointSequence prone = lie_down();  // turned a half turn about the body's long axis (Z): face down
    for (int j = 0; j < kNumJoints; ++j) {
        Vector3d& p = prone.at(4, j);
        p = Vector3d(-p.x(), 0.2 - p.y(), p.z());
    }
    const JointSequence m = lying_still(prone, LyingOptions{});
    double floor = prone.at(4, 0).y();  // the pose's lowest joint: the hands, resting under the body
    for (int j = 0; j < kNumJoints; ++j) floor = std::min(floor, prone.at(4, j).y());
    for (int f = 0; f < m.num_frames; ++f)
        for (int j = 0; j < kNumJoints; ++j)
            EXPECT_GE(m.at(f, j).y(), floor - 1e-12) << kJointNames[static_cast<size_t>(j)];
    EXPECT_GT(m.at(43, head).y(), prone.at(4, head).y() + 0.005);
}

TEST(LyingStill, RefusesAClipThatEndsStandingOrBadOptions) {
    JointSequence standing = lie_down();
    standing.num_frames = 1;
    standing.positions.resize(kNumJoints);
    EXPECT_THROW(lying_still(standing, LyingOptions{}), Error);
    LyingOptions o;
    o.breaths_per_min = 40;
    try {
        lying_still(lie_down(), o);
        FAIL() << "accepted 40 breaths/min";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("breaths_per_min"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace t2imu
