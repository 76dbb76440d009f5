// Motion quality scores against motions whose answers are known by construction.
#include <gtest/gtest.h>

#include "motion/motion_quality.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {
namespace {

// A standing figure: joints spread from the floor (feet at y = 0) up to 1.7 m, 20 fps.
JointSequence standing(int frames) {
    JointSequence m(frames, smpl22::kNumJoints, 20.0);
    for (int f = 0; f < frames; ++f)
        for (int j = 0; j < smpl22::kNumJoints; ++j) m.at(f, j) = Eigen::Vector3d(0.01 * j, 1.7 * j / 21.0, 0.0);
    for (int f = 0; f < frames; ++f)
        for (int j : {smpl22::left_ankle, smpl22::left_foot, smpl22::right_ankle, smpl22::right_foot})
            m.at(f, j).y() = 0.0;
    return m;
}

TEST(MotionQuality, StaticPoseScoresZero) {
    const MotionQuality q = score_motion(standing(40));
    EXPECT_DOUBLE_EQ(q.foot_skate_m_s, 0.0);
    EXPECT_DOUBLE_EQ(q.penetration_m, 0.0);
    EXPECT_DOUBLE_EQ(q.hover_m, 0.0);
    EXPECT_DOUBLE_EQ(q.max_speed_m_s, 0.0);
    EXPECT_DOUBLE_EQ(q.max_acc_m_s2, 0.0);
    EXPECT_DOUBLE_EQ(q.pelvis_acc_m_s2, 0.0);
    EXPECT_TRUE(quality_failures(q, default_quality_thresholds()).empty());
}

TEST(MotionQuality, SlidingPlantedFeetSkateAtTheSlideSpeed) {
    // The whole body glides along +X at 2 m/s with its feet on the floor: skating = 2 m/s, no acceleration.
    JointSequence m = standing(40);
    for (int f = 0; f < m.num_frames; ++f)
        for (int j = 0; j < m.num_joints; ++j) m.at(f, j).x() += 2.0 * f / m.fps;
    const MotionQuality q = score_motion(m);
    EXPECT_NEAR(q.foot_skate_m_s, 2.0, 1e-9);
    EXPECT_NEAR(q.max_speed_m_s, 2.0, 1e-9);
    EXPECT_NEAR(q.max_acc_m_s2, 0.0, 1e-6);
    EXPECT_EQ(quality_failures(q, default_quality_thresholds()), std::vector<std::string>{"foot_skate"});
    EXPECT_NEAR(quality_badness(q, default_quality_thresholds()), 2.0 / 1.3, 1e-9);
}

TEST(MotionQuality, LiftedFeetDoNotCountAsSkating) {
    // The same glide 0.5 m above the floor is hovering, not skating.
    JointSequence m = standing(40);
    for (int f = 0; f < m.num_frames; ++f)
        for (int j = 0; j < m.num_joints; ++j) m.at(f, j) += Eigen::Vector3d(2.0 * f / m.fps, 0.5, 0.0);
    const MotionQuality q = score_motion(m);
    EXPECT_DOUBLE_EQ(q.foot_skate_m_s, 0.0);
    EXPECT_NEAR(q.hover_m, 0.5, 1e-12);
    EXPECT_EQ(quality_failures(q, default_quality_thresholds()), std::vector<std::string>{"hover"});
}

TEST(MotionQuality, PenetrationIsTheDeepestJointBelowTheFloor) {
    JointSequence m = standing(40);
    m.at(10, smpl22::left_foot).y() = -0.12;
    const MotionQuality q = score_motion(m);
    EXPECT_NEAR(q.penetration_m, 0.12, 1e-12);
    EXPECT_DOUBLE_EQ(q.hover_m, 0.0);
    // One frame's dip and return: |Δ²y| = 0.24 m per frame² = 96 m/s²; 0.12 m in one frame = 2.4 m/s.
    EXPECT_NEAR(q.max_acc_m_s2, 0.24 * 400, 1e-9);
    EXPECT_NEAR(q.max_speed_m_s, 2.4, 1e-9);
}

TEST(MotionQuality, ATeleportingPelvisFailsThePelvisScoreThatTheAllJointScoreLetsThrough) {
    // A generated lying-down draw as measured, turned sideways to keep the feet on the floor: the whole body
    // jumps 0.52 m in one frame, half back, and again (pelvis height 0.74, 0.22, 0.55, 0.22 m). Pelvis |Δ²x| at
    // the first frame: 0.52 + 0.33 = 0.85 m per frame² = 340 m/s² at 20 fps, under max_acc's 350 (which hands
    // and feet need) and well over the pelvis's 60; the feet's skating averages 0.6 m/s over the clip.
    JointSequence m = standing(40);
    for (int f = 21; f < m.num_frames; ++f)
        for (int j = 0; j < m.num_joints; ++j) m.at(f, j).x() += f == 22 ? 0.19 : 0.52;
    const MotionQuality q = score_motion(m);
    EXPECT_NEAR(q.pelvis_acc_m_s2, 0.85 * 400, 1e-9);
    EXPECT_NEAR(q.max_acc_m_s2, 0.85 * 400, 1e-9);
    EXPECT_EQ(quality_failures(q, default_quality_thresholds()), std::vector<std::string>{"pelvis_acc"});
    // A hand that snaps as fast moves no pelvis: the all-joint score sees it, the pelvis score does not.
    JointSequence snap = standing(40);
    snap.at(20, smpl22::left_wrist).y() += 0.5;
    const MotionQuality h = score_motion(snap);
    EXPECT_NEAR(h.max_acc_m_s2, 2 * 0.5 * 400, 1e-9);
    EXPECT_DOUBLE_EQ(h.pelvis_acc_m_s2, 0.0);
}

TEST(MotionQuality, PlacingOnTheFloorTurnsAUniformSinkIntoNothingAndAPartialOneIntoHover) {
    // Sunk 0.3 m for the whole clip: placed back exactly, every score as the standing pose's.
    JointSequence sunk = standing(40);
    for (int f = 0; f < sunk.num_frames; ++f)
        for (int j = 0; j < sunk.num_joints; ++j) sunk.at(f, j).y() -= 0.3;
    EXPECT_NEAR(score_motion(sunk).penetration_m, 0.3, 1e-12);
    EXPECT_NEAR(place_on_floor(sunk), 0.3, 1e-12);
    const JointSequence reference = standing(40);
    for (int f = 0; f < sunk.num_frames; ++f)
        for (int j = 0; j < sunk.num_joints; ++j) EXPECT_NEAR((sunk.at(f, j) - reference.at(f, j)).norm(), 0.0, 1e-12);
    EXPECT_TRUE(quality_failures(score_motion(sunk), default_quality_thresholds()).empty());
    // Sunk 0.4 m for the last 15 of 40 frames: placed on that level, the other 25 frames stand 0.4 m above it.
    JointSequence partly = standing(40);
    for (int f = 25; f < partly.num_frames; ++f)
        for (int j = 0; j < partly.num_joints; ++j) partly.at(f, j).y() -= 0.4;
    EXPECT_NEAR(place_on_floor(partly), 0.4, 1e-12);
    const MotionQuality q = score_motion(partly);
    EXPECT_DOUBLE_EQ(q.penetration_m, 0.0);
    EXPECT_NEAR(q.hover_m, 0.4, 1e-12);
}

TEST(MotionQuality, OnRaisedGroundHeightsCountFromTheGroundUnderEachJoint) {
    // The standing figure on a 0.5 m platform, gliding along +X at 2 m/s: above the floor it only hovers; on
    // the platform as its ground it skates at 2 m/s and does not hover. Half a metre lower is 0.5 m through it.
    JointSequence m = standing(40);
    for (int f = 0; f < m.num_frames; ++f)
        for (int j = 0; j < m.num_joints; ++j) m.at(f, j) += Eigen::Vector3d(2.0 * f / m.fps, 0.5, 0.0);
    const GroundHeight platform = [](const Eigen::Vector3d&, int) { return 0.5; };
    EXPECT_NEAR(score_motion(m).hover_m, 0.5, 1e-12);
    const MotionQuality q = score_motion_on_ground(m, platform);
    EXPECT_NEAR(q.foot_skate_m_s, 2.0, 1e-9);
    EXPECT_NEAR(q.hover_m, 0.0, 1e-12);
    EXPECT_NEAR(q.max_speed_m_s, score_motion(m).max_speed_m_s, 1e-12);
    for (int f = 0; f < m.num_frames; ++f)
        for (int j = 0; j < m.num_joints; ++j) m.at(f, j).y() -= 0.5;
    EXPECT_NEAR(score_motion_on_ground(m, platform).penetration_m, 0.5, 1e-12);
}

TEST(MotionQuality, RefusesTooFewFrames) { EXPECT_THROW(score_motion(standing(2)), Error); }

}  // namespace
}  // namespace t2imu
