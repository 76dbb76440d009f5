// Motion descriptors on motions with known answers: a hand-built body gliding at 1 m/s (speeds, upright angles,
// heights), the airborne threshold, a seated and a lying posture (thigh tilt, knee flexion, trunk tilt), a bounce
// (height sd), left-right mirror symmetry, the moments over a set and refused input; and HumanML3D's rest skeleton
// moved rigidly: walking pace, lying on the back, climbing up and down, a jump.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/error.hpp"
#include "motion/motion_descriptors.hpp"
#include "motion/skeleton.hpp"
#include "pose_fixture.hpp"

using namespace t2imu;
using Eigen::Vector3d;
namespace j = smpl22;

namespace {
enum Descriptor {
    kPelvisHeight,
    kPelvisSd,
    kHeadAbove,
    kTrunk,
    kThigh,
    kKnee,
    kRootSpeed,
    kVerticalSd,
    kClimb,
    kFootSpeed,
    kWristSpeed,
    kAirborne
};

// `frames` frames at 20 fps of the pose `pose` moved by offset(f) (and each joint by joint_offset(f, joint)).
template <class Offset>
JointSequence motion(int frames, const std::array<Vector3d, 22>& pose, Offset offset) {
    JointSequence m(frames, 22, 20.0);
    for (int f = 0; f < frames; ++f)
        for (int k = 0; k < 22; ++k) m.at(f, k) = pose[static_cast<size_t>(k)] + offset(f, k);
    return m;
}
}  // namespace

TEST(MotionDescriptors, GlidingUprightAtOneMetrePerSecond) {
    // Every joint moves at (0.8, 0, 0.6) m/s: horizontal speed 1, feet at 1, wrists still relative to the pelvis.
    const MotionDescriptors d = describe_motion(
        motion(40, test::standing_pose(), [](int f, int) -> Vector3d { return Vector3d(0.8, 0, 0.6) * f / 20.0; }));
    EXPECT_NEAR(d[kPelvisHeight], 0.9, 1e-12);
    EXPECT_NEAR(d[kPelvisSd], 0.0, 1e-12);
    EXPECT_NEAR(d[kHeadAbove], 0.65, 1e-12);
    EXPECT_NEAR(d[kTrunk], 0.0, 1e-7);
    EXPECT_NEAR(d[kThigh], 0.0, 1e-7);
    EXPECT_NEAR(d[kKnee], 0.0, 1e-7);
    EXPECT_NEAR(d[kRootSpeed], 1.0, 1e-12);
    EXPECT_NEAR(d[kVerticalSd], 0.0, 1e-12);
    EXPECT_NEAR(d[kClimb], 0.0, 1e-12);
    EXPECT_NEAR(d[kFootSpeed], 1.0, 1e-12);
    EXPECT_NEAR(d[kWristSpeed], 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(d[kAirborne], 0.0);
    EXPECT_STREQ(kMotionDescriptorNames[kClimb], "climb_rate_m_s");
}

TEST(MotionDescriptors, AirborneMeansMoreThanFiveCentimetresUp) {
    // The whole body lifted in frames 10..14 of 40: 6 cm is flight (5 frames), 4 cm is below kAirborneHeight.
    const auto lifted = [](double h) {
        return describe_motion(motion(40, test::standing_pose(), [h](int f, int) -> Vector3d {
            return Vector3d(0, f >= 10 && f < 15 ? h : 0.0, 0);
        }));
    };
    EXPECT_DOUBLE_EQ(lifted(0.06)[kAirborne], 5.0 / 40);
    EXPECT_DOUBLE_EQ(lifted(0.04)[kAirborne], 0.0);
}

TEST(MotionDescriptors, SeatedAndLyingPostures) {
    // Seated: thighs horizontal (knees 0.45 m in front of the hips), shins vertical: thigh tilt pi/2, knee bent pi/2.
    std::array<Vector3d, 22> seated = test::standing_pose();
    for (int side : {-1, 1}) {
        const bool left = side > 0;
        seated[left ? j::left_hip : j::right_hip] = {0.1 * side, 0.5, 0};
        seated[left ? j::left_knee : j::right_knee] = {0.1 * side, 0.5, 0.45};
        seated[left ? j::left_ankle : j::right_ankle] = {0.1 * side, 0.05, 0.45};
    }
    const MotionDescriptors s =
        describe_motion(motion(10, seated, [](int, int) -> Vector3d { return Vector3d::Zero(); }));
    EXPECT_NEAR(s[kThigh], M_PI / 2, 1e-12);
    EXPECT_NEAR(s[kKnee], M_PI / 2, 1e-12);
    // Lying: the standing body turned 90 deg about X (head towards +Z) and lowered to 0.15 m: trunk and thighs
    // tilted pi/2, the head level with the pelvis.
    std::array<Vector3d, 22> lying;
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitX()).toRotationMatrix();
    for (size_t k = 0; k < 22; ++k)
        lying[k] = turn * (test::standing_pose()[k] - Vector3d(0, 0.9, 0)) + Vector3d(0, 0.15, 0);
    const MotionDescriptors l =
        describe_motion(motion(10, lying, [](int, int) -> Vector3d { return Vector3d::Zero(); }));
    EXPECT_NEAR(l[kTrunk], M_PI / 2, 1e-12);
    EXPECT_NEAR(l[kThigh], M_PI / 2, 1e-12);
    EXPECT_NEAR(l[kHeadAbove], 0.0, 1e-12);
    EXPECT_NEAR(l[kPelvisHeight], 0.15, 1e-12);
}

TEST(MotionDescriptors, BounceAndWristSwing) {
    // Pelvis and body bounce 0.05 sin(2 pi 2 t) m over 4 whole cycles: population sd 0.05 / sqrt(2). Wrists
    // move forward at 0.5 m/s relative to the pelvis.
    const MotionDescriptors d = describe_motion(motion(40, test::standing_pose(), [](int f, int k) -> Vector3d {
        const double t = f / 20.0;
        const bool wrist = k == j::left_wrist || k == j::right_wrist;
        return Vector3d(0, 0.05 * std::sin(2 * M_PI * 2 * t), wrist ? 0.5 * t : 0.0);
    }));
    EXPECT_NEAR(d[kPelvisHeight], 0.9, 1e-12);
    EXPECT_NEAR(d[kPelvisSd], 0.05 / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(d[kWristSpeed], 0.5, 1e-12);
    // Finite differences of the bounce: amplitude 2 x 0.05 sin(pi 2 / 20) x 20 m/s, sd about amplitude / sqrt 2.
    EXPECT_NEAR(d[kVerticalSd], 2 * 0.05 * std::sin(M_PI * 2 / 20) * 20 / std::sqrt(2.0), 0.02);
}

TEST(MotionDescriptors, MirroredMotionHasTheSameDescriptors) {
    // Mirror: x -> -x and left <-> right joints swapped (kMirror).
    const JointSequence m = motion(30, test::standing_pose(), [](int f, int k) -> Vector3d {
        return Vector3d(0.3 * f / 20.0 + 0.01 * k * std::sin(f * 0.7), 0.02 * std::cos(f * 0.5 + k), 0.7 * f / 20.0);
    });
    JointSequence mirrored = m;
    for (int f = 0; f < m.num_frames; ++f)
        for (int k = 0; k < 22; ++k) {
            const Vector3d p = m.at(f, j::kMirror[static_cast<size_t>(k)]);
            mirrored.at(f, k) = Vector3d(-p.x(), p.y(), p.z());
        }
    const MotionDescriptors a = describe_motion(m), b = describe_motion(mirrored);
    for (size_t i = 0; i < kNumMotionDescriptors; ++i) EXPECT_NEAR(a[i], b[i], 1e-12) << kMotionDescriptorNames[i];
}

TEST(MotionDescriptors, MomentsOverASet) {
    MotionDescriptors a{}, b{};
    a[0] = 1, b[0] = 3;
    a[5] = -2, b[5] = -2;
    const DescriptorMoments m = descriptor_moments({a, b});
    EXPECT_DOUBLE_EQ(m.mean[0], 2.0);
    EXPECT_DOUBLE_EQ(m.sd[0], 1.0);  // population sd
    EXPECT_DOUBLE_EQ(m.mean[5], -2.0);
    EXPECT_DOUBLE_EQ(m.sd[5], 0.0);
    const DescriptorMoments none = descriptor_moments({});
    for (size_t i = 0; i < kNumMotionDescriptors; ++i) {
        EXPECT_EQ(none.mean[i], 0.0);
        EXPECT_EQ(none.sd[i], 0.0);
    }
}

TEST(MotionDescriptors, RefusesTooFewFramesOrJoints) {
    EXPECT_THROW(
        describe_motion(motion(2, test::standing_pose(), [](int, int) -> Vector3d { return Vector3d::Zero(); })),
        Error);
    EXPECT_THROW(describe_motion(JointSequence(10, 21, 20.0)), Error);
}

// HumanML3D's rest skeleton moved rigidly (these tests were in test_motion_activity.cpp).
namespace t2imu {
namespace {

// HumanML3D's target skeleton in its rest pose (upright, legs straight, facing +Z), lowest joint on the floor.
std::array<Eigen::Vector3d, smpl22::kNumJoints> rest_pose() {
    std::array<Eigen::Vector3d, smpl22::kNumJoints> p;
    for (int j = 0; j < smpl22::kNumJoints; ++j)
        p[j] = smpl22::kParents[j] < 0 ? Eigen::Vector3d(Eigen::Vector3d::Zero())
                                       : Eigen::Vector3d(p[smpl22::kParents[j]] + smpl22::kTargetOffsets[j]);
    double lowest = INFINITY;
    for (const Eigen::Vector3d& x : p) lowest = std::min(lowest, x.y());
    for (Eigen::Vector3d& x : p) x.y() -= lowest;
    return p;
}

// The rest pose rotated by `pose` about the pelvis, then displaced by offset(t) at t = frame / 20 s.
template <class Offset>
JointSequence rigid_motion(int frames, const Eigen::Matrix3d& pose, Offset offset) {
    const auto rest = rest_pose();
    JointSequence m(frames, smpl22::kNumJoints, smpl22::kFps);
    for (int f = 0; f < frames; ++f)
        for (int j = 0; j < smpl22::kNumJoints; ++j)
            m.at(f, j) = rest[0] + pose * (rest[j] - rest[0]) + offset(f / smpl22::kFps);
    return m;
}

double descriptor(const MotionDescriptors& d, const std::string& name) {
    for (size_t i = 0; i < kNumMotionDescriptors; ++i)
        if (name == kMotionDescriptorNames[i]) return d[i];
    ADD_FAILURE() << "no descriptor " << name;
    return NAN;
}

TEST(MotionDescriptors, WalkingPaceTranslationOfAnUprightBody) {
    const MotionDescriptors d = describe_motion(
        rigid_motion(60, Eigen::Matrix3d::Identity(), [](double t) { return Eigen::Vector3d(0, 0, 1.2 * t); }));
    EXPECT_NEAR(descriptor(d, "root_speed_m_s"), 1.2, 1e-9);
    EXPECT_NEAR(descriptor(d, "foot_speed_m_s"), 1.2, 1e-9);
    EXPECT_NEAR(descriptor(d, "wrist_speed_m_s"), 0.0, 1e-9);  // relative to the pelvis
    EXPECT_NEAR(descriptor(d, "pelvis_height_sd_m"), 0.0, 1e-9);
    EXPECT_NEAR(descriptor(d, "root_vertical_speed_sd_m_s"), 0.0, 1e-9);
    EXPECT_NEAR(descriptor(d, "climb_rate_m_s"), 0.0, 1e-9);
    EXPECT_EQ(descriptor(d, "airborne_fraction"), 0.0);
    // Upright: legs straight under the hips, trunk vertical, head about 0.5 m over the pelvis, pelvis about 0.9 m up.
    EXPECT_LT(descriptor(d, "thigh_tilt_rad"), 0.1);
    EXPECT_LT(descriptor(d, "knee_flexion_rad"), 0.1);
    EXPECT_LT(descriptor(d, "trunk_tilt_rad"), 0.15);
    EXPECT_GT(descriptor(d, "head_above_pelvis_m"), 0.4);
    EXPECT_NEAR(descriptor(d, "pelvis_height_m"), 0.9, 0.1);
}

TEST(MotionDescriptors, LyingBodyHasItsHeadAtPelvisHeight) {
    // Rotated -90 degrees about X: the head points along -Z, the face up. The rest skeleton carries its head
    // about 0.1 m forward of the spine, which lying on the back turns into height.
    const Eigen::Matrix3d on_back = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
    const MotionDescriptors d =
        describe_motion(rigid_motion(40, on_back, [](double) { return Eigen::Vector3d::Zero(); }));
    EXPECT_NEAR(descriptor(d, "head_above_pelvis_m"), 0.0, 0.15);
    EXPECT_NEAR(descriptor(d, "trunk_tilt_rad"), M_PI / 2, 0.15);
    EXPECT_NEAR(descriptor(d, "thigh_tilt_rad"), M_PI / 2, 0.1);
    EXPECT_NEAR(descriptor(d, "root_speed_m_s"), 0.0, 1e-12);
}

TEST(MotionDescriptors, SteadyClimbIsNotFlight) {
    const MotionDescriptors d = describe_motion(
        rigid_motion(80, Eigen::Matrix3d::Identity(), [](double t) { return Eigen::Vector3d(0, 0.2 * t, 0.4 * t); }));
    EXPECT_NEAR(descriptor(d, "climb_rate_m_s"), 0.2, 1e-9);
    EXPECT_NEAR(descriptor(d, "root_vertical_speed_sd_m_s"), 0.0, 1e-9);
    EXPECT_EQ(descriptor(d, "airborne_fraction"), 0.0);
    // Going down the same slope: the sign tells stairs down from up.
    const MotionDescriptors down = describe_motion(rigid_motion(
        80, Eigen::Matrix3d::Identity(), [](double t) { return Eigen::Vector3d(0, 1.0 - 0.2 * t, 0.4 * t); }));
    EXPECT_NEAR(descriptor(down, "climb_rate_m_s"), -0.2, 1e-9);
}

TEST(MotionDescriptors, JumpIsAirborneForItsFlightFrames) {
    // 60 frames on the floor but frames 20..29, 0.3 m up: 10 of 60 frames in flight.
    const MotionDescriptors d = describe_motion(rigid_motion(60, Eigen::Matrix3d::Identity(), [](double t) {
        const int f = static_cast<int>(std::lround(t * smpl22::kFps));
        return Eigen::Vector3d(0, f >= 20 && f < 30 ? 0.3 : 0.0, 0);
    }));
    EXPECT_NEAR(descriptor(d, "airborne_fraction"), 10.0 / 60.0, 1e-12);
    EXPECT_NEAR(descriptor(d, "climb_rate_m_s"), 0.0, 0.02);
}

TEST(MotionDescriptors, RefusesTooFewFrames) {
    EXPECT_THROW(describe_motion(JointSequence(2, smpl22::kNumJoints, 20.0)), Error);
}

}  // namespace
}  // namespace t2imu
