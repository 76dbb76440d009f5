// Stair gait derived from a procedural level walk whose geometry is known exactly (feet flat on the floor in
// stance, toe 2 cm and ankle 8 cm above it, pelvis at 0.82 m), and from a captured walk when the shared mocap
// is at hand.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/error.hpp"
#include "motion/mocap_import.hpp"
#include "motion/motion_edit.hpp"
#include "motion/motion_quality.hpp"
#include "motion/skeleton.hpp"
#include "motion/stair_gait.hpp"
#include "motion/two_bone_ik.hpp"
#include "test_util.hpp"
#include "walk_fixture.hpp"

namespace t2imu {
namespace {

using Eigen::Vector3d;
using namespace smpl22;

using test::kAnkleHeight;
using test::kToeHeight;
using test::kWalkPelvisHeight;
using test::procedural_walk;

StairOptions stairs(bool ascend, double rise = 0.17) {
    StairOptions o = default_stair_options(ascend);
    o.rise_m = rise;
    return o;
}

double lowest_toe(const JointSequence& m, const StairFoothold& h) {
    double low = 1e9;
    for (int f = h.first_frame; f <= h.last_frame; ++f)
        low = std::min(low, m.at(f, kLegs[static_cast<size_t>(h.foot)].toe).y());
    return low;
}

TEST(StairGait, TheProceduralWalkIsAValidSource) {
    const JointSequence walk = procedural_walk(6.0);
    EXPECT_LT(max_bone_length_error(walk, bone_lengths(walk, 0)), 1e-9);
    EXPECT_TRUE(quality_failures(score_motion(walk), default_quality_thresholds()).empty());
}

TEST(StairGait, EveryStanceFootStandsOnItsOwnTreadStepOverStep) {
    const StairMotion s = derive_stairs(procedural_walk(6.0), stairs(true));
    ASSERT_GE(s.stairs.steps, 6);
    ASSERT_GE(s.footholds.size(), 6u);
    for (size_t i = 0; i < s.footholds.size(); ++i) {
        const StairFoothold& h = s.footholds[i];
        EXPECT_NEAR(lowest_toe(s.motion, h), h.tread * 0.17 + kToeHeight, 1e-3) << "foothold " << i;
        if (i > 0) {
            EXPECT_EQ(h.tread, s.footholds[i - 1].tread + 1) << "one tread per step";
        }
        // The foot's middle over the middle of its tread, whose depth is the going.
        const LegJoints& leg = kLegs[static_cast<size_t>(h.foot)];
        const int mid = (h.first_frame + h.last_frame) / 2;
        const double along = s.stairs.along(0.5 * (s.motion.at(mid, leg.ankle) + s.motion.at(mid, leg.toe)));
        EXPECT_NEAR(along, s.stairs.start_m + (h.tread + 0.5) * 0.28, 0.03) << "foothold " << i;
    }
    EXPECT_EQ(s.footholds.back().tread, s.stairs.steps);
}

TEST(StairGait, NoJointGoesThroughATread) {
    for (bool ascend : {true, false}) {
        const StairMotion s = derive_stairs(procedural_walk(6.0), stairs(ascend));
        double deepest = 0;
        for (int f = 0; f < s.motion.num_frames; ++f)
            for (int j = 0; j < kNumJoints; ++j)
                deepest = std::max(deepest, s.stairs.height_at(s.motion.at(f, j)) - s.motion.at(f, j).y());
        EXPECT_LE(deepest, 0.0) << (ascend ? "ascent" : "descent");
    }
}

TEST(StairGait, TheClimbGainsOneRisePerStep) {
    const StairMotion s = derive_stairs(procedural_walk(6.0), stairs(true));
    const StairFoothold &first = s.footholds.front(), &last = s.footholds.back();
    EXPECT_NEAR(lowest_toe(s.motion, last) - lowest_toe(s.motion, first), (last.tread - first.tread) * 0.17, 1e-3);
    const int end = s.motion.num_frames - 1;  // the leading foot ends on the top tread
    EXPECT_NEAR(
        std::max(s.stairs.height_at(s.motion.at(end, left_foot)), s.stairs.height_at(s.motion.at(end, right_foot))),
        s.stairs.steps * 0.17, 1e-12);
    // The pelvis rises with the feet: over the clip by the rise times the treads climbed, within one step.
    const double pelvis_gain = s.motion.at(s.motion.num_frames - 1, pelvis).y() - s.motion.at(0, pelvis).y();
    EXPECT_NEAR(pelvis_gain, (last.tread - first.tread) * 0.17, 0.17);
}

TEST(StairGait, DescentIsTheAscentReversed) {
    const StairMotion up = derive_stairs(procedural_walk(6.0), stairs(true));
    const StairMotion down = derive_stairs(procedural_walk(6.0), stairs(false));
    ASSERT_EQ(up.stairs.steps, down.stairs.steps);
    const int steps = down.stairs.steps;
    for (const StairFoothold& h : down.footholds)
        EXPECT_NEAR(lowest_toe(down.motion, h), (steps - h.tread) * 0.17 + kToeHeight, 1e-3);
    EXPECT_NEAR(down.stairs.tread_height(0), steps * 0.17, 1e-12);
    EXPECT_NEAR(down.stairs.tread_height(steps), 0.0, 1e-12);
    // Both walk forward (+Z): the descent goes down as far as the ascent goes up.
    const auto gain = [](const JointSequence& m) { return m.at(m.num_frames - 1, pelvis).y() - m.at(0, pelvis).y(); };
    EXPECT_LT(gain(down.motion), -0.5);
    EXPECT_NEAR(gain(down.motion), -gain(up.motion), 0.17);
    EXPECT_GT(down.motion.at(down.motion.num_frames - 1, pelvis).z(), down.motion.at(0, pelvis).z() + 1.0);
}

TEST(StairGait, BonesKeepTheirLengths) {
    const JointSequence walk = procedural_walk(6.0);
    for (bool ascend : {true, false})
        EXPECT_LT(max_bone_length_error(walk_to_stairs(walk, stairs(ascend)), bone_lengths(walk, 0)), 1e-6);
}

TEST(StairGait, WithoutRiseThePelvisStaysAtTheWalksHeight) {
    StairOptions o = stairs(true, 0.0);
    o.cadence_factor = 1.0;
    const JointSequence m = walk_to_stairs(procedural_walk(6.0), o);
    for (int f = 0; f < m.num_frames; ++f) EXPECT_NEAR(m.at(f, pelvis).y(), kWalkPelvisHeight, 3e-3) << "frame " << f;
}

TEST(StairGait, StepsShortenToTheGoingAndTheCadenceSlows) {
    // Source: 0.5 m steps, 2 steps a second. Stairs: 0.28 m steps at the default ascent pace (0.72).
    const StairMotion s = derive_stairs(procedural_walk(6.0), stairs(true));
    const StairFoothold &a = s.footholds[1], &b = s.footholds[5];
    const double step_time = (b.first_frame - a.first_frame) / kFps / 4;
    EXPECT_NEAR(step_time, 0.5 / default_stair_options(true).cadence_factor, 1.0 / kFps);
    const double travel = s.motion.at(b.first_frame, pelvis).z() - s.motion.at(a.first_frame, pelvis).z();
    EXPECT_NEAR(travel / 4, 0.28, 0.02);
}

TEST(StairGait, ClimbingBendsTheKneesMoreAndLeansTheTrunk) {
    const JointSequence walk = procedural_walk(6.0);
    const JointSequence up = walk_to_stairs(walk, stairs(true));
    auto peak_knee = [](const JointSequence& m) {
        double peak = 0;
        for (int f = 0; f < m.num_frames; ++f)
            peak = std::max({peak, knee_flexion_rad(m, f, 0), knee_flexion_rad(m, f, 1)});
        return peak;
    };
    EXPECT_GT(peak_knee(up), peak_knee(walk) + 0.3);
    // The rest-pose trunk is upright: pelvis -> neck leans forward by the option's angle.
    const Vector3d trunk = up.at(10, neck) - up.at(10, pelvis);
    EXPECT_NEAR(std::atan2(trunk.z(), trunk.y()), 0.12, 1e-9);
}

// Root mean square of the pelvis's vertical acceleration (m/s^2, second differences).
double pelvis_vertical_acceleration_rms(const JointSequence& m) {
    double sum = 0;
    for (int f = 1; f + 1 < m.num_frames; ++f) {
        const double a = (m.at(f + 1, pelvis).y() - 2 * m.at(f, pelvis).y() + m.at(f - 1, pelvis).y()) * m.fps * m.fps;
        sum += a * a;
    }
    return std::sqrt(sum / (m.num_frames - 2));
}

TEST(StairGait, TheEditIsTheSameAtAnyFrameRate) {
    // The same walk at 20 and 60 fps climbs the same flight with the same body motion: every smoothing and
    // threshold of the edit counts seconds. (Counted in frames, the 60 fps body rose with a third of the
    // smoothing: its vertical acceleration was 23 times larger.)
    for (bool ascend : {true, false}) {
        const StairMotion at_20 = derive_stairs(procedural_walk(8), stairs(ascend));
        const StairMotion at_60 = derive_stairs(procedural_walk(8, 60), stairs(ascend));
        EXPECT_EQ(at_60.stairs.steps, at_20.stairs.steps);
        EXPECT_EQ(at_60.footholds.size(), at_20.footholds.size());
        EXPECT_NEAR(at_60.motion.num_frames / 60.0, at_20.motion.num_frames / 20.0, 0.1);
        const double rms_20 = pelvis_vertical_acceleration_rms(at_20.motion),
                     rms_60 = pelvis_vertical_acceleration_rms(at_60.motion);
        EXPECT_NEAR(rms_60, rms_20, 0.2 * rms_20) << rms_60 << " against " << rms_20;
    }
}

TEST(StairGait, PassesTheQualityCheckAgainstTheTreads) {
    for (bool ascend : {true, false}) {
        const StairMotion s = derive_stairs(procedural_walk(6.0), stairs(ascend));
        const MotionQuality q =
            score_motion_on_ground(s.motion, [&](const Vector3d& p, int) { return s.stairs.height_at(p); });
        EXPECT_TRUE(quality_failures(q, default_quality_thresholds()).empty())
            << "skate " << q.foot_skate_m_s << " acc " << q.max_acc_m_s2 << " pelvis acc " << q.pelvis_acc_m_s2
            << " hover " << q.hover_m;
        EXPECT_LT(q.pelvis_acc_m_s2, 30.0);
    }
}

TEST(StairGait, RefusesBadOptionsNamingTheField) {
    StairOptions o = stairs(true);
    o.going_m = 0.10;
    try {
        walk_to_stairs(procedural_walk(6.0), o);
        FAIL() << "accepted a 10 cm going";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("going_m"), std::string::npos) << e.what();
    }
    o = stairs(true, 0.30);
    EXPECT_THROW(validate(o), Error);
}

TEST(StairGait, RefusesAMotionThatDoesNotWalk) {
    JointSequence still = procedural_walk(6.0);
    for (int f = 0; f < still.num_frames; ++f)
        still.positions[static_cast<size_t>(f * kNumJoints)] = still.at(0, pelvis);
    EXPECT_THROW(walk_to_stairs(still, stairs(true)), Error);
}

TEST(StairGait, RefusesAWalkBackward) {
    // The walk played in reverse travels along -Z facing +Z.
    const JointSequence walk = procedural_walk(6.0);
    JointSequence back = walk;
    for (int f = 0; f < walk.num_frames; ++f)
        for (int j = 0; j < kNumJoints; ++j) back.at(f, j) = walk.at(walk.num_frames - 1 - f, j);
    EXPECT_THROW(walk_to_stairs(back, stairs(true)), Error);
}

TEST(StairGait, ACapturedWalkClimbsAndDescends) {
    const std::string dir = test::unpacked_shared_archive("mocap/bandai_bvh_native.tar.xz");
    if (dir.empty()) GTEST_SKIP() << "shared data not found: mocap/bandai_bvh_native.tar.xz";
    JointSequence walk = import_motion(dir + "/bandai_bvh/dataset-2_walk_normal_001.bvh");
    place_on_floor(walk);
    for (bool ascend : {true, false}) {
        const StairMotion s = derive_stairs(walk, stairs(ascend));
        EXPECT_LT(max_bone_length_error(s.motion, bone_lengths(walk, 0)), 1e-6);
        const MotionQuality q =
            score_motion_on_ground(s.motion, [&](const Vector3d& p, int) { return s.stairs.height_at(p); });
        double peak_knee = 0;
        for (int f = 0; f < s.motion.num_frames; ++f)
            peak_knee = std::max({peak_knee, knee_flexion_rad(s.motion, f, 0), knee_flexion_rad(s.motion, f, 1)});
        std::printf(
            "[captured %s] frames %d, steps %d, footholds %zu, knee peak %.1f deg, skate %.2f m/s, "
            "penetration %.3f m, hover %.3f m, max acc %.0f, pelvis acc %.1f m/s^2\n",
            ascend ? "ascent" : "descent", s.motion.num_frames, s.stairs.steps, s.footholds.size(),
            peak_knee * 180 / test::kPi, q.foot_skate_m_s, q.penetration_m, q.hover_m, q.max_acc_m_s2,
            q.pelvis_acc_m_s2);
        EXPECT_GE(s.stairs.steps, 4);
        EXPECT_TRUE(quality_failures(q, default_quality_thresholds()).empty());
    }
}

}  // namespace
}  // namespace t2imu
