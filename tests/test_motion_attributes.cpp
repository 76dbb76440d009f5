// Motion attributes on motions whose answers are known: a rigid glide at exactly 1.2 m/s, the procedural walk
// (1 m/s, two steps a second: cadence 120, stride 1 m), that walk turned gradually left and mirrored (right),
// played backward in time (walking backward), replayed on stairs up and down (step count and tread rise), a
// body lifted in a parabola (one jump, its height), lying on the back, front and left side, and a sit-to-stand
// sequence (the order of transitions).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/error.hpp"
#include "motion/motion_attributes.hpp"
#include "motion/skeleton.hpp"
#include "motion/stair_gait.hpp"
#include "pose_fixture.hpp"
#include "walk_fixture.hpp"

using namespace t2imu;
using Eigen::Vector3d;
namespace j = smpl22;

namespace {

// A seated body: thighs forward and level at 0.5 m, shins vertical, trunk upright over the pelvis.
std::array<Vector3d, 22> seated() {
    std::array<Vector3d, 22> p = test::standing_pose();
    const double drop = 0.4;
    for (int k : {j::pelvis, j::spine1, j::spine2, j::spine3, j::neck, j::head, j::left_hip, j::right_hip,
                  j::left_collar, j::right_collar, j::left_shoulder, j::right_shoulder, j::left_elbow, j::right_elbow,
                  j::left_wrist, j::right_wrist})
        p[static_cast<size_t>(k)].y() -= drop;
    for (int side : {-1, 1}) {
        const bool left = side > 0;
        p[left ? j::left_knee : j::right_knee] = {0.1 * side, 0.45, 0.4};
        p[left ? j::left_ankle : j::right_ankle] = {0.1 * side, 0.05, 0.4};
        p[left ? j::left_foot : j::right_foot] = {0.1 * side, 0.0, 0.5};
    }
    return p;
}

JointSequence still(const std::array<Vector3d, 22>& pose, int frames) {
    JointSequence m(frames, 22, 20.0);
    for (int f = 0; f < frames; ++f)
        for (int k = 0; k < 22; ++k) m.at(f, k) = pose[static_cast<size_t>(k)];
    return m;
}

// `m` rotated about the vertical through the origin by angle(f) at frame f (rad, + towards +X: a left turn).
template <class Angle>
JointSequence turned(const JointSequence& m, Angle angle) {
    JointSequence out = m;
    for (int f = 0; f < m.num_frames; ++f) {
        const Eigen::Matrix3d r = Eigen::AngleAxisd(angle(f), Vector3d::UnitY()).toRotationMatrix();
        for (int k = 0; k < 22; ++k) out.at(f, k) = r * m.at(f, k);
    }
    return out;
}

// The left-right mirror image: x negated, left and right joints swapped (smpl22::kMirror).
JointSequence mirrored(const JointSequence& s) {
    JointSequence out = s;
    for (int f = 0; f < s.num_frames; ++f)
        for (int k = 0; k < s.num_joints; ++k) {
            Vector3d p = s.at(f, j::kMirror[static_cast<size_t>(k)]);
            p.x() = -p.x();
            out.at(f, k) = p;
        }
    return out;
}

// Every joint of `pose` laid down rigidly by rotation r about the origin, then lifted so the lowest joint is 0.05 m up.
JointSequence laid(const Eigen::Matrix3d& r, int frames) {
    std::array<Vector3d, 22> p = test::standing_pose();
    double low = 1e9;
    for (Vector3d& x : p) x = r * (x - Vector3d(0, 0.9, 0)), low = std::min(low, x.y());
    for (Vector3d& x : p) x.y() += 0.05 - low;
    return still(p, frames);
}

}  // namespace

TEST(MotionAttributes, AGlideAtExactlyOnePointTwoMetresPerSecondMeasuresOnePointTwo) {
    JointSequence m = still(test::standing_pose(), 80);
    for (int f = 0; f < m.num_frames; ++f)
        for (int k = 0; k < 22; ++k) m.at(f, k) += Vector3d(0.72, 0, 0.96) * f / 20.0;  // |(0.72, 0.96)| = 1.2
    const MotionAttributes a = measure_attributes(m);
    EXPECT_NEAR(a.ground_speed_m_s, 1.2, 1e-9);
    EXPECT_NEAR(a.distance_m, 1.2 * 79 / 20.0, 1e-9);
    EXPECT_NEAR(a.duration_s, 79 / 20.0, 1e-12);
    EXPECT_EQ(a.travel, TravelDirection::forward);  // 36.9 deg left of its facing (+Z): within 45 deg of forward
}

TEST(MotionAttributes, TheProceduralWalkHasItsSpeedCadenceAndStride) {
    const MotionAttributes a = measure_attributes(test::procedural_walk(8.0));
    EXPECT_NEAR(a.ground_speed_m_s, 1.0, 0.02);
    EXPECT_NEAR(a.cadence_steps_min, 120, 8);
    EXPECT_NEAR(a.stride_length_m, 1.0, 0.08);
    EXPECT_NEAR(a.heading_change_deg, 0, 1);
    EXPECT_NEAR(a.path_turn_deg, 0, 1);
    EXPECT_EQ(a.travel, TravelDirection::forward);
    EXPECT_EQ(a.steps_up + a.steps_down, 0);
    EXPECT_EQ(a.jumps, 0);
    EXPECT_DOUBLE_EQ(a.seated_s + a.lying_s, 0.0);
    EXPECT_EQ(a.lying_side, LyingSide::none);
    EXPECT_TRUE(a.transitions.empty());
    EXPECT_NEAR(a.trunk_lean_deg, 0, 1);
}

TEST(MotionAttributes, AWalkTurnedGraduallyLeftTurnsLeftAndItsMirrorRight) {
    const JointSequence walk = test::procedural_walk(8.0);
    const double total = M_PI / 2;  // 90 deg over the clip
    const JointSequence left = turned(walk, [&](int f) { return total * f / (walk.num_frames - 1); });
    const MotionAttributes a = measure_attributes(left);
    EXPECT_NEAR(a.heading_change_deg, 90 * (1 - 10.0 / 159), 3);  // first and last half second averaged
    EXPECT_GT(a.path_turn_deg, 70);
    EXPECT_EQ(a.travel, TravelDirection::forward);
    const MotionAttributes b = measure_attributes(mirrored(left));
    EXPECT_NEAR(b.heading_change_deg, -a.heading_change_deg, 1e-6);
    EXPECT_NEAR(b.path_turn_deg, -a.path_turn_deg, 1e-6);
    EXPECT_NEAR(b.ground_speed_m_s, a.ground_speed_m_s, 1e-9);
}

TEST(MotionAttributes, AWalkPlayedBackwardInTimeWalksBackward) {
    const JointSequence walk = test::procedural_walk(6.0);
    JointSequence back = walk;
    for (int f = 0; f < walk.num_frames; ++f)
        for (int k = 0; k < 22; ++k) back.at(f, k) = walk.at(walk.num_frames - 1 - f, k);
    const MotionAttributes a = measure_attributes(back);
    EXPECT_EQ(a.travel, TravelDirection::backward);
    EXPECT_NEAR(a.ground_speed_m_s, 1.0, 0.02);
    EXPECT_NEAR(a.heading_change_deg, 0, 1);
}

TEST(MotionAttributes, StairsUpAndDownCountTheirStepsAndTheRise) {
    for (bool ascend : {true, false}) {
        StairOptions o = default_stair_options(ascend);
        o.rise_m = 0.17;
        const StairMotion s = derive_stairs(test::procedural_walk(8.0), o);
        const MotionAttributes a = measure_attributes(s.motion);
        const int treads = s.footholds.back().tread - s.footholds.front().tread;
        SCOPED_TRACE(ascend ? "up" : "down");
        EXPECT_EQ(ascend ? a.steps_up : a.steps_down, treads);
        EXPECT_EQ(ascend ? a.steps_down : a.steps_up, 0);
        EXPECT_NEAR(a.step_height_m, 0.17, 0.02);
        EXPECT_NEAR(a.rise_m, (ascend ? 1 : -1) * 0.17 * treads, 0.05);
        ASSERT_FALSE(a.transitions.empty());
        EXPECT_EQ(a.transitions.front(), ascend ? Transition::climb_up : Transition::climb_down);
    }
}

TEST(MotionAttributes, UpThenDownIsTwoClimbsInThatOrder) {
    const StairMotion up = derive_stairs(test::procedural_walk(8.0), default_stair_options(true));
    const StairMotion down = derive_stairs(test::procedural_walk(8.0), default_stair_options(false));
    // Down starts where up ends: lift it by the height it lost, move it to the end of the climb.
    const Vector3d shift = up.motion.at(up.motion.num_frames - 1, j::pelvis) - down.motion.at(0, j::pelvis);
    JointSequence rest = down.motion;
    for (Vector3d& p : rest.positions) p += shift;
    const MotionAttributes a = measure_attributes(concatenate_frames(up.motion, rest));
    ASSERT_GE(a.transitions.size(), 2u);
    EXPECT_EQ(a.transitions[0], Transition::climb_up);
    EXPECT_EQ(a.transitions[1], Transition::climb_down);
    EXPECT_GT(a.steps_up, 2);
    EXPECT_GT(a.steps_down, 2);
}

TEST(MotionAttributes, ABodyLiftedInAParabolaJumpsOnceAtItsHeight) {
    JointSequence m = still(test::standing_pose(), 60);
    for (int f = 20; f <= 30; ++f) {  // 0.5 s of flight, peak 0.3 m at frame 25
        const double t = (f - 25) / 5.0, h = 0.3 * (1 - t * t);
        for (int k = 0; k < 22; ++k) m.at(f, k).y() += h;
    }
    const MotionAttributes a = measure_attributes(m);
    EXPECT_EQ(a.jumps, 1);
    EXPECT_NEAR(a.jump_height_m, 0.3, 1e-9);
    JointSequence low = still(test::standing_pose(), 60);  // a 0.08 m hop stays under kJumpRise
    for (int f = 22; f <= 28; ++f)
        for (int k = 0; k < 22; ++k) low.at(f, k).y() += 0.08;
    EXPECT_EQ(measure_attributes(low).jumps, 0);
}

TEST(MotionAttributes, LyingOnTheBackTheFrontAndTheLeftSide) {
    const auto side_of = [](const Eigen::Matrix3d& r) { return measure_attributes(laid(r, 40)).lying_side; };
    const Eigen::Matrix3d back =
        Eigen::AngleAxisd(-M_PI / 2, Vector3d::UnitX()).toRotationMatrix();  // belly (+Z) to +Y
    const Eigen::Matrix3d front = Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitX()).toRotationMatrix();
    // On the left side: laid on the back (head to -Z), then rolled about the body's long axis so its left (+X) points
    // down.
    const Eigen::Matrix3d left = Eigen::AngleAxisd(-M_PI / 2, Vector3d::UnitZ()).toRotationMatrix() * back;
    EXPECT_EQ(side_of(back), LyingSide::back);
    EXPECT_EQ(side_of(front), LyingSide::front);
    const MotionAttributes a = measure_attributes(laid(left, 40));
    EXPECT_EQ(a.lying_side, LyingSide::left);
    EXPECT_NEAR(a.lying_s, 40 / 20.0, 1e-9);
    EXPECT_EQ(measure_attributes(mirrored(laid(left, 40))).lying_side, LyingSide::right);
}

TEST(MotionAttributes, SittingDownAndStandingUpInThatOrder) {
    const JointSequence m = concatenate_frames(
        concatenate_frames(still(test::standing_pose(), 20), still(seated(), 40)), still(test::standing_pose(), 20));
    const MotionAttributes a = measure_attributes(m);
    ASSERT_EQ(a.transitions.size(), 2u);
    EXPECT_EQ(a.transitions[0], Transition::sit_down);
    EXPECT_EQ(a.transitions[1], Transition::stand_up);
    EXPECT_NEAR(a.seated_s, 2.0, 1e-9);
    EXPECT_STREQ(transition_name(a.transitions[0]), "sit_down");
    // A two-frame dip into the seat is not a sit (shorter than kMinPostureSeconds).
    const JointSequence dip = concatenate_frames(
        concatenate_frames(still(test::standing_pose(), 20), still(seated(), 2)), still(test::standing_pose(), 20));
    EXPECT_TRUE(measure_attributes(dip).transitions.empty());
}

TEST(MotionAttributes, RefusesAMotionThatIsNotTwentyTwoJointsOrTooShort) {
    EXPECT_THROW(measure_attributes(still(test::standing_pose(), 2)), Error);
    EXPECT_THROW(measure_attributes(JointSequence(10, 21, 20.0)), Error);
}
