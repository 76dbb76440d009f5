// Jumps rescaled in height and chained into series: a procedural jump whose flight is an exact projectile, so the
// derived flight's acceleration, apex and duration have known answers (g, k^2 h, k T), and a series of it travels
// and turns by known amounts.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "imu/imu_synthesis.hpp"
#include "motion/foot_contacts.hpp"
#include "motion/jump_rescale.hpp"
#include "motion/jump_series.hpp"
#include "motion/motion_edit.hpp"
#include "motion/skeleton.hpp"
#include "motion/two_bone_ik.hpp"
#include "test_util.hpp"

namespace t2imu {
namespace {

using Eigen::Vector3d;
using namespace smpl22;

constexpr double kJumpStandPelvisHeight = 0.88;
constexpr int kJumpStandFrames = 20, kJumpFlightFrames = 10;  // 1 s standing either side, 0.5 s in the air
constexpr double kJumpTravel = 0.4;                           // m travelled in the air, +Z

// Pelvis lift above standing at time t into the flight (s): a projectile that leaves and meets the floor level.
double jump_projectile_lift(double t) {
    const double flight_s = kJumpFlightFrames / kFps;
    return 0.5 * kGravity * t * (flight_s - t);
}

// Standing facing +Z, knees slightly bent, then a rigid jump forward: the whole body follows the projectile.
JointSequence procedural_jump() {
    const int frames = 2 * kJumpStandFrames + kJumpFlightFrames;
    JointSequence m(frames, kNumJoints, kFps);
    for (int f = 0; f < frames; ++f) {
        const int in_air = std::clamp(f - kJumpStandFrames, 0, kJumpFlightFrames);
        const double t = in_air / kFps;
        const Vector3d shift(0, jump_projectile_lift(t), kJumpTravel * in_air / kJumpFlightFrames);
        m.at(f, pelvis) = Vector3d(0, kJumpStandPelvisHeight, 0) + shift;
        for (int j = 1; j < kNumJoints; ++j)
            if (!is_leg_joint(j))
                m.at(f, j) = m.at(f, kParents[static_cast<size_t>(j)]) + kTargetOffsets[static_cast<size_t>(j)];
        for (const LegJoints& leg : kLegs) {
            const double foot = kTargetOffsets[static_cast<size_t>(leg.toe)].norm();
            m.at(f, leg.ankle) = Vector3d(kTargetOffsets[static_cast<size_t>(leg.hip)].x(), 0.08, 0) + shift;
            m.at(f, leg.toe) = m.at(f, leg.ankle) + Vector3d(0, -0.06, std::sqrt(foot * foot - 0.06 * 0.06));
            m.at(f, leg.knee) = solve_two_bone_ik(m.at(f, leg.hip), m.at(f, leg.ankle),
                                                  kTargetOffsets[static_cast<size_t>(leg.knee)].norm(),
                                                  kTargetOffsets[static_cast<size_t>(leg.ankle)].norm(),
                                                  m.at(f, leg.hip) + Vector3d(0, -0.4, 1))
                                    .middle;
        }
    }
    return m;
}

struct MeasuredFlight {
    int frames = 0;           // frames with both feet in the air
    double apex_m = 0;        // highest pelvis lift above standing
    double acceleration = 0;  // m/s^2, twice the quadratic coefficient of a least-squares parabola
};

MeasuredFlight measure_jump_flight(const JointSequence& m) {
    const std::vector<bool> left = stance_frames(m, Foot::left), right = stance_frames(m, Foot::right);
    std::vector<double> t, y;
    for (int f = 0; f < m.num_frames; ++f)
        if (!left[static_cast<size_t>(f)] && !right[static_cast<size_t>(f)]) {
            t.push_back(f / m.fps);
            y.push_back(m.at(f, pelvis).y() - kJumpStandPelvisHeight);
        }
    MeasuredFlight out;
    out.frames = static_cast<int>(t.size());
    // The first and last frame in the air are left out of the fit: the procedural take-off and landing are
    // kinks (the speed jumps in one frame), which the retiming's cubic rounds over a frame either side.
    if (t.size() >= 5) {
        t = std::vector<double>(t.begin() + 1, t.end() - 1);
        y = std::vector<double>(y.begin() + 1, y.end() - 1);
    }
    if (t.size() < 3) return out;
    Eigen::MatrixXd a(static_cast<long>(t.size()), 3);
    Eigen::VectorXd b(static_cast<long>(t.size()));
    for (size_t i = 0; i < t.size(); ++i) {
        a.row(static_cast<long>(i)) << 1, t[i], t[i] * t[i];
        b(static_cast<long>(i)) = y[i];
    }
    const Eigen::Vector3d c = a.colPivHouseholderQr().solve(b);
    out.acceleration = 2 * c(2);
    out.apex_m = c(0) - c(1) * c(1) / (4 * c(2));
    return out;
}

TEST(JumpRescale, TheProceduralJumpIsAProjectile) {
    const MeasuredFlight f = measure_jump_flight(procedural_jump());
    EXPECT_EQ(f.frames, kJumpFlightFrames - 1);  // the frames strictly between leaving and meeting the floor
    EXPECT_NEAR(f.acceleration, -kGravity, 1e-6);
    EXPECT_NEAR(f.apex_m, kGravity * 0.25 / 8, 1e-6);  // g T^2 / 8, T = 0.5 s
}

TEST(JumpRescale, TheFlightStaysBallisticWithApexKSquaredAndDurationK) {
    const JointSequence jump = procedural_jump();
    const MeasuredFlight before = measure_jump_flight(jump);
    for (double k : {0.9, 1.12, 1.2}) {
        JumpRescaleOptions o;
        o.time_scale = k;
        const JointSequence m = rescale_jump(jump, o);
        const MeasuredFlight after = measure_jump_flight(m);
        std::printf("[k %.2f] flight %d frames, apex %.3f m, acceleration %.2f m/s^2\n", k, after.frames, after.apex_m,
                    after.acceleration);
        EXPECT_NEAR(after.acceleration, -kGravity, 0.01 * kGravity) << "k " << k;
        EXPECT_NEAR(after.apex_m, k * k * before.apex_m, 0.01) << "k " << k;
        EXPECT_NEAR(after.frames, k * kJumpFlightFrames - 1, 1.0) << "k " << k;
        // Horizontal travel is kept, at 1/k of the speed.
        const double travel = m.at(m.num_frames - 1, pelvis).z() - m.at(0, pelvis).z();
        EXPECT_NEAR(travel, kJumpTravel, 1e-6) << "k " << k;
        EXPECT_NEAR(m.num_frames, k * (jump.num_frames - 1) + 1, 1.0);
        EXPECT_LT(max_bone_length_error(m, bone_lengths(jump, 0)), 1e-6) << "k " << k;
    }
}

TEST(JumpRescale, FeetOnTheFloorStayThere) {
    JumpRescaleOptions o;
    o.time_scale = 1.2;
    const JointSequence m = rescale_jump(procedural_jump(), o);
    const std::vector<bool> left = stance_frames(m, Foot::left);
    int planted = 0;
    for (int f = 0; f < m.num_frames; ++f) {
        if (!left[static_cast<size_t>(f)]) continue;
        ++planted;
        EXPECT_NEAR(m.at(f, left_ankle).y(), 0.08, 1e-6) << "frame " << f;
        EXPECT_NEAR(m.at(f, left_foot).y(), 0.02, 1e-6) << "frame " << f;
    }
    EXPECT_GT(planted, 40);
}

TEST(JumpRescale, ScaleOneIsTheIdentity) {
    const JointSequence jump = procedural_jump();
    JumpRescaleOptions o;
    o.time_scale = 1.0;
    const JointSequence m = rescale_jump(jump, o);
    ASSERT_EQ(m.num_frames, jump.num_frames);
    double most = 0;
    for (size_t i = 0; i < m.positions.size(); ++i) most = std::max(most, (m.positions[i] - jump.positions[i]).norm());
    EXPECT_LT(most, 1e-6);
}

TEST(JumpRescale, RefusesScalesOutOfRangeAndShortClips) {
    JumpRescaleOptions o;
    o.time_scale = 1.5;
    EXPECT_TRUE(test::contains(test::error_message([&] { rescale_jump(procedural_jump(), o); }), "time_scale"));
    o.time_scale = 1.1;
    EXPECT_TRUE(
        test::contains(test::error_message([&] { rescale_jump(slice_frames(procedural_jump(), 0, 5), o); }), "0.5 s"));
}

// The jump turned about the vertical through the origin by `angle` (rad, x towards z).
JointSequence turned(JointSequence m, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    for (Vector3d& p : m.positions) p = Vector3d(c * p.x() - s * p.z(), p.y(), s * p.x() + c * p.z());
    return m;
}

TEST(JumpSeries, ChainedJumpsKeepEachFlightAndTravelOnFromEachLanding) {
    const JointSequence jump = procedural_jump();
    const JumpSeriesOptions o;  // 0.1 s: 2 frames at 20 fps
    const int blend = 2, step = jump.num_frames - blend;
    const JointSequence m = chain_jumps({jump, jump, jump}, o);
    ASSERT_EQ(m.num_frames, 3 * jump.num_frames - 2 * blend);
    for (int i = 0; i < 3; ++i) {
        // Each jump's flight is the captured one: the blends fall where both feet stand.
        const MeasuredFlight f = measure_jump_flight(slice_frames(m, i * step, i * step + jump.num_frames));
        EXPECT_EQ(f.frames, kJumpFlightFrames - 1) << "jump " << i;
        EXPECT_NEAR(f.acceleration, -kGravity, 1e-6) << "jump " << i;
    }
    // Each jump starts where the last landed: three jumps travel three times as far, straight on.
    EXPECT_NEAR(m.at(m.num_frames - 1, pelvis).z() - m.at(0, pelvis).z(), 3 * kJumpTravel, 1e-6);
    EXPECT_NEAR(m.at(m.num_frames - 1, pelvis).x(), m.at(0, pelvis).x(), 1e-6);
    EXPECT_LT(max_bone_length_error(m, bone_lengths(jump, 0)), 1e-6);
}

TEST(JumpSeries, ANextJumpTurnsToFaceTheWayThePreviousOneEnds) {
    const JointSequence jump = procedural_jump();            // faces and travels +Z
    const JointSequence sideways = turned(jump, -M_PI / 2);  // faces and travels +X
    const JointSequence m = chain_jumps({jump, sideways}, JumpSeriesOptions{});
    const Vector3d facing = body_facing(m, m.num_frames - 1);
    EXPECT_NEAR(facing.z(), 1.0, 1e-6);
    EXPECT_NEAR(m.at(m.num_frames - 1, pelvis).z() - m.at(0, pelvis).z(), 2 * kJumpTravel, 1e-6);
    EXPECT_NEAR(m.at(m.num_frames - 1, pelvis).x() - m.at(0, pelvis).x(), 0.0, 1e-6);
}

TEST(JumpSeries, RefusesOneJumpMixedRatesAndBlendsOutOfRange) {
    const JointSequence jump = procedural_jump();
    EXPECT_TRUE(test::contains(test::error_message([&] { chain_jumps({jump}, JumpSeriesOptions{}); }), "two jumps"));
    JointSequence faster = jump;
    faster.fps = 40;
    EXPECT_TRUE(test::contains(test::error_message([&] {
                                   chain_jumps({jump, faster}, JumpSeriesOptions{});
                               }),
                               "one frame rate"));
    JumpSeriesOptions o;
    o.blend_s = 0.5;
    EXPECT_TRUE(test::contains(test::error_message([&] { chain_jumps({jump, jump}, o); }), "blend_s"));
    EXPECT_TRUE(test::contains(test::error_message([&] {
                                   chain_jumps({jump, slice_frames(jump, 0, 5)}, JumpSeriesOptions{});
                               }),
                               "three blend windows"));
}

}  // namespace
}  // namespace t2imu
