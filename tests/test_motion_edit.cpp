// The editing building blocks on small figures whose answers follow from geometry.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "motion/motion_edit.hpp"
#include "motion/skeleton.hpp"
#include "test_util.hpp"

namespace t2imu {
namespace {

using Eigen::Vector3d;
using namespace smpl22;

// HumanML3D's target skeleton in its rest pose (upright, arms down, legs straight), pelvis at `pelvis_height`.
JointSequence rest_pose(int frames, double pelvis_height = 1.0) {
    JointSequence m(frames, kNumJoints, kFps);
    for (int f = 0; f < frames; ++f) {
        m.at(f, pelvis) = Vector3d(0, pelvis_height, 0);
        for (int j = 1; j < kNumJoints; ++j)
            m.at(f, j) = m.at(f, kParents[static_cast<size_t>(j)]) + kTargetOffsets[static_cast<size_t>(j)];
    }
    return m;
}

TEST(MotionEdit, RestoringBoneLengthsKeepsDirectionsAndCarriesChildren) {
    JointSequence m = rest_pose(1);
    const BoneLengths target = bone_lengths(m, 0);
    m.at(0, left_knee).y() -= 0.1;  // thigh 10 cm too long; shank 10 cm too short
    restore_bone_lengths(m, target);
    EXPECT_LT(max_bone_length_error(m, target), 1e-12);
    const JointSequence rest = rest_pose(1);
    EXPECT_NEAR((m.at(0, left_knee) - rest.at(0, left_knee)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((m.at(0, left_ankle) - rest.at(0, left_ankle)).norm(), 0.0, 1e-12);
}

TEST(MotionEdit, RetimingHalvesTheSpeedWithoutOvershoot) {
    // The whole figure glides 0.1 m per frame along X for 10 frames and stands still for 10.
    JointSequence m = rest_pose(21);
    for (int f = 0; f < m.num_frames; ++f)
        for (int j = 0; j < kNumJoints; ++j) m.at(f, j).x() += 0.1 * std::min(f, 10);
    const JointSequence slow = retime(m, 0.5);
    ASSERT_EQ(slow.num_frames, 41);
    EXPECT_NEAR(slow.at(9, pelvis).x(), 0.45, 1e-12);  // halfway between source frames 4 and 5
    EXPECT_NEAR(slow.at(40, pelvis).x(), 1.0, 1e-12);
    for (int g = 20; g < slow.num_frames; ++g) EXPECT_LE(slow.at(g, pelvis).x(), 1.0 + 1e-12) << "frame " << g;
    EXPECT_LT(max_bone_length_error(slow, bone_lengths(m, 0)), 1e-9);
    EXPECT_THROW(retime(m, 0.1), Error);
}

TEST(MotionEdit, TurnedToFaceTurnsAboutThePivotAndMovesItThere) {
    const JointSequence m = rest_pose(3);
    const Vector3d facing0 = body_facing(m, 0), pivot = m.at(1, left_foot), to(2, 7, -1);
    // A quarter turn: the body faces its old facing turned 90 deg about the vertical (x towards z).
    const Vector3d facing(-facing0.z(), 0, facing0.x());
    const JointSequence t = turned_to_face(m, 1, facing, pivot, to);
    EXPECT_LT((body_facing(t, 1) - facing).norm(), 1e-12);
    for (int f = 0; f < m.num_frames; ++f)
        for (int j = 0; j < kNumJoints; ++j) {
            EXPECT_DOUBLE_EQ(t.at(f, j).y(), m.at(f, j).y());            // heights unchanged
            const Vector3d a = m.at(f, j) - pivot, b = t.at(f, j) - to;  // horizontal distance to the pivot kept
            EXPECT_NEAR(std::hypot(a.x(), a.z()), std::hypot(b.x(), b.z()), 1e-12);
        }
    EXPECT_NEAR(t.at(1, left_foot).x(), 2, 1e-12);  // the pivot stands at `to` horizontally
    EXPECT_NEAR(t.at(1, left_foot).z(), -1, 1e-12);
}

TEST(MotionEdit, MinimumJerkStartsAndEndsAtRest) {
    EXPECT_DOUBLE_EQ(min_jerk(0.0), 0.0);
    EXPECT_DOUBLE_EQ(min_jerk(0.5), 0.5);
    EXPECT_DOUBLE_EQ(min_jerk(1.0), 1.0);
    EXPECT_DOUBLE_EQ(min_jerk(-3.0), 0.0);
    EXPECT_DOUBLE_EQ(min_jerk(7.0), 1.0);
    const double h = 1e-4;
    EXPECT_NEAR((min_jerk(h) - min_jerk(0)) / h, 0.0, 1e-6);
    EXPECT_NEAR((min_jerk(1) - min_jerk(1 - h)) / h, 0.0, 1e-6);
    EXPECT_NEAR((min_jerk(0.5 + h) - min_jerk(0.5 - h)) / (2 * h), 1.875, 1e-6);  // peak speed 15/8
}

TEST(MotionEdit, FlexingTheTrunkTurnsItAboutThePelvisAndLeavesTheLegs) {
    const JointSequence rest = rest_pose(1);
    JointSequence m = rest;
    flex_trunk(m, 0, Vector3d::UnitZ(), test::kPi / 6);
    const Vector3d before = rest.at(0, spine3) - rest.at(0, pelvis), after = m.at(0, spine3) - m.at(0, pelvis);
    EXPECT_NEAR(std::atan2(after.z(), after.y()) - std::atan2(before.z(), before.y()), test::kPi / 6, 1e-12);
    EXPECT_GT(m.at(0, head).z(), rest.at(0, head).z() + 0.2);
    for (int j : {pelvis, left_hip, right_hip, left_knee, right_ankle, left_foot})
        EXPECT_EQ(m.at(0, j), rest.at(0, j)) << kJointNames[static_cast<size_t>(j)];
    EXPECT_LT(max_bone_length_error(m, bone_lengths(rest, 0)), 1e-12);
}

TEST(MotionEdit, TheUpperEnvelopeIsSmoothAndNeverBelow) {
    std::vector<double> x(30, 0.0);
    x[10] = 1.0;
    x[11] = 0.5;
    const std::vector<double> e = upper_envelope(x, 4);
    for (size_t i = 0; i < x.size(); ++i) EXPECT_GE(e[i], x[i]);
    EXPECT_NEAR(e[10], 1.0, 1e-12);  // flat top: the running maximum covers the whole kernel there
    EXPECT_DOUBLE_EQ(e[0], 0.0);
    EXPECT_DOUBLE_EQ(e[29], 0.0);
}

TEST(MotionEdit, LoweringBringsEveryHipWithinReachAndLeavesTheLegs) {
    // Legs straight (0.826 m left, 0.816 m right from hip to ankle), asked to reach 0.80 m: the body comes down
    // 0.826 - 0.80 = 0.026 m (the left leg decides; both ankles sit straight below their hips).
    JointSequence m = rest_pose(10);
    const JointSequence rest = m;
    const double drop = lower_to_reach(m, {0.80, 0.80});
    EXPECT_NEAR(drop, (rest.at(0, left_hip) - rest.at(0, left_ankle)).norm() - 0.80, 1e-9);
    for (int f = 0; f < m.num_frames; ++f) {
        EXPECT_NEAR(m.at(f, head).y(), rest.at(f, head).y() - drop, 1e-9);
        EXPECT_EQ(m.at(f, left_ankle), rest.at(f, left_ankle));
        for (size_t k = 0; k < 2; ++k) EXPECT_LE((m.at(f, kLegs[k].hip) - m.at(f, kLegs[k].ankle)).norm(), 0.80 + 1e-9);
    }
}

TEST(MotionEdit, PlacingKneesBendsThemForwardWithTheirLengths) {
    JointSequence m = rest_pose(1, 1.0);
    const JointSequence source = m;
    const BoneLengths lengths = bone_lengths(source, 0);
    for (int j = 0; j < kNumJoints; ++j)
        if (!is_leg_joint(j)) m.at(0, j).y() -= 0.2;  // squat 20 cm over planted feet
    EXPECT_TRUE(place_knees(m, source, Vector3d::UnitZ(), lengths));
    EXPECT_LT(max_bone_length_error(m, lengths), 1e-9);
    for (size_t k = 0; k < 2; ++k) {
        EXPECT_GT(m.at(0, kLegs[k].knee).z(), 0.1);  // forward
        EXPECT_EQ(m.at(0, kLegs[k].ankle), source.at(0, kLegs[k].ankle));
    }
    // Law of cosines: hip-ankle distance d = straight leg - 0.2 gives the flexion.
    const double a = lengths[left_knee], b = lengths[left_ankle], d = a + b - 0.2;
    EXPECT_NEAR(knee_flexion_rad(m, 0, 0), test::kPi - std::acos((a * a + b * b - d * d) / (2 * a * b)), 1e-9);
    EXPECT_NEAR(knee_flexion_rad(source, 0, 0), 0.0, 1e-6);
}

}  // namespace
}  // namespace t2imu
