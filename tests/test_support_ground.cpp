// The ground a motion stands on, on motions whose ground is known: a procedural level walk (feet flat on the
// floor in stance, toe 2 cm above it), the same walk carried up and down a staircase by stair_gait (treads known
// exactly), that walk lifted into the air or drifting upward, a climb whose foot goes through its tread, and
// every stair flight derived from the shared captured walks.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "core/error.hpp"
#include "motion/mocap_import.hpp"
#include "motion/motion_quality.hpp"
#include "motion/resample.hpp"
#include "motion/skeleton.hpp"
#include "motion/stair_gait.hpp"
#include "motion/support_ground.hpp"
#include "test_util.hpp"
#include "walk_fixture.hpp"

namespace t2imu {
namespace {

using Eigen::Vector3d;

StairMotion flight(bool ascend) {
    StairOptions o = default_stair_options(ascend);
    o.rise_m = 0.17;
    return derive_stairs(test::procedural_walk(6.0), o);
}

bool fails(const MotionQuality& q, const std::string& score) {
    const std::vector<std::string> f = quality_failures(q, default_quality_thresholds());
    return std::find(f.begin(), f.end(), score) != f.end();
}

TEST(SupportGround, ALevelWalkStandsOnTheFloorEverywhere) {
    const JointSequence walk = test::procedural_walk(6.0);
    const std::vector<Foothold> holds = infer_footholds(walk);
    ASSERT_GE(holds.size(), 10u);  // 12 steps in 6 s, the first and last maybe cut
    for (const Foothold& h : holds) {
        EXPECT_NEAR(h.height, test::kToeHeight, 1e-9);
        EXPECT_TRUE(h.grounded);
        EXPECT_FALSE(h.raised);
    }
    const SupportGround ground(walk);
    EXPECT_TRUE(ground.raised_footholds().empty());
    const MotionQuality q = score_motion(walk);
    EXPECT_NEAR(q.hover_m, test::kToeHeight, 1e-9);
    EXPECT_TRUE(quality_failures(q, default_quality_thresholds()).empty());
}

TEST(SupportGround, StairFootholdsStandOnTheirTreads) {
    for (bool ascend : {true, false}) {
        const StairMotion s = flight(ascend);
        const SupportGround ground(s.motion);
        ASSERT_GE(ground.raised_footholds().size(), 4u) << (ascend ? "ascent" : "descent");
        // Each stance foot's ground is its tread's height plus the toe's 2 cm (the floor's own: 0). The first and
        // last stances are cut by the clip's ends, maybe shorter than a stance that counts.
        for (size_t k = 1; k + 1 < s.footholds.size(); ++k) {
            const StairFoothold& h = s.footholds[k];
            const int f = (h.first_frame + h.last_frame) / 2,
                      toe = h.foot == Foot::left ? smpl22::left_foot : smpl22::right_foot;
            const Vector3d& p = s.motion.at(f, toe);
            EXPECT_NEAR(ground.height_at(p, f),
                        s.stairs.height_at(p) < 0.1 ? 0.0 : s.stairs.height_at(p) + test::kToeHeight, 1e-3)
                << (ascend ? "ascent" : "descent") << ", tread " << h.tread;
        }
        // Above the floor alone the flight hovers (what the filter measured before); above its footholds it passes.
        const MotionQuality on_floor = score_motion_on_ground(s.motion, [](const Vector3d&, int) { return 0.0; });
        EXPECT_TRUE(fails(on_floor, "hover")) << on_floor.hover_m;
        const MotionQuality q = score_motion(s.motion);
        EXPECT_TRUE(quality_failures(q, default_quality_thresholds()).empty())
            << "hover " << q.hover_m << " penetration " << q.penetration_m << " skate " << q.foot_skate_m_s;
        EXPECT_LT(q.hover_m, 0.05);
    }
}

TEST(SupportGround, ALevelWalkRaisedIntoTheAirHovers) {
    JointSequence walk = test::procedural_walk(6.0);
    for (int f = 0; f < walk.num_frames; ++f)
        for (int j = 0; j < walk.num_joints; ++j) walk.at(f, j).y() += 0.5;
    for (const Foothold& h : infer_footholds(walk)) EXPECT_FALSE(h.grounded);
    const MotionQuality q = score_motion(walk);
    EXPECT_NEAR(q.hover_m, 0.5 + test::kToeHeight, 1e-9);
    EXPECT_TRUE(fails(q, "hover"));
}

TEST(SupportGround, ABodyThatRisesWithoutLandingOnTreadsHovers) {
    // The level walk drifting up 0.34 m/s, a 0.17 m riser per step at two steps a second: the feet never stand
    // still vertically, so no foothold carries the body up and the climb is read as floating off the floor.
    JointSequence walk = test::procedural_walk(6.0);
    for (int f = 0; f < walk.num_frames; ++f)
        for (int j = 0; j < walk.num_joints; ++j) walk.at(f, j).y() += 0.34 * f / walk.fps;
    EXPECT_TRUE(SupportGround(walk).raised_footholds().empty());
    EXPECT_TRUE(fails(score_motion(walk), "hover"));
    // A sudden sink: standing 0.4 m up, then on the floor after one frame, in the same place, is no step down.
    JointSequence sink = test::procedural_walk(2.0);
    for (int f = 0; f < sink.num_frames; ++f)
        for (int j = 0; j < sink.num_joints; ++j)
            sink.at(f, j) = sink.at(0, j) + Vector3d(0, f < sink.num_frames / 2 ? 0.4 : 0.0, 0);
    EXPECT_TRUE(SupportGround(sink).raised_footholds().empty());
    EXPECT_TRUE(fails(score_motion(sink), "hover"));
}

TEST(SupportGround, AFootThroughItsTreadIsPenetration) {
    // The ascent with one foot pushed 0.2 m down in the two frames after it leaves a raised tread: it goes
    // through the tread it stood on.
    StairMotion s = flight(true);
    const SupportGround ground(s.motion);
    const Foothold* lift = nullptr;
    for (const Foothold& h : ground.raised_footholds())
        if (h.until_frame < s.motion.num_frames && h.until_frame - h.phase.last_frame > 4) {
            lift = &h;
            break;
        }
    ASSERT_NE(lift, nullptr);
    const std::array<int, 2>& foot = lift->phase.foot == Foot::left ? smpl22::kFootLeft : smpl22::kFootRight;
    for (int f = lift->phase.last_frame + 1; f <= lift->phase.last_frame + 2; ++f)
        for (int j : foot) s.motion.at(f, j).y() -= 0.2;
    const MotionQuality q = score_motion(s.motion);
    EXPECT_GT(q.penetration_m, 0.1);
    EXPECT_TRUE(fails(q, "penetration"));
}

TEST(SupportGround, AHeldPoseIsNoStepUp) {
    // Standing on the floor with one foot held still 0.3 m up for a second: the held foot carries nothing, so
    // it is no raised ground, and a joint below it later is no penetration.
    JointSequence m = test::procedural_walk(2.0);
    for (int f = 0; f < m.num_frames; ++f)
        for (int j = 0; j < m.num_joints; ++j) m.at(f, j) = m.at(0, j);
    for (int f = 0; f < 20; ++f)
        for (int j : smpl22::kFootLeft) m.at(f, j).y() += 0.3;
    const std::vector<Foothold> holds = infer_footholds(m);
    EXPECT_TRUE(std::any_of(holds.begin(), holds.end(), [](const Foothold& h) { return h.height > 0.3; }));
    EXPECT_TRUE(std::none_of(holds.begin(), holds.end(), [](const Foothold& h) { return h.raised; }));
    EXPECT_DOUBLE_EQ(score_motion(m).penetration_m, 0.0);
}

TEST(SupportGround, EveryFlightDerivedFromTheSharedWalksPasses) {
    const std::string dir = test::unpacked_shared_archive("mocap/bandai_bvh_native.tar.xz");
    if (dir.empty()) GTEST_SKIP() << "shared data not found: mocap/bandai_bvh_native.tar.xz";
    std::vector<std::string> walks;
    for (const auto& e : std::filesystem::directory_iterator(dir + "/bandai_bvh"))
        if (e.path().filename().string().find("_walk_") != std::string::npos) walks.push_back(e.path().string());
    std::sort(walks.begin(), walks.end());
    ASSERT_GE(walks.size(), 20u);
    int flights = 0;
    for (const std::string& file : walks) {
        JointSequence walk = import_motion(file);
        place_on_floor(walk);
        for (bool ascend : {true, false}) {
            StairMotion s;
            try {
                s = derive_stairs(walk, default_stair_options(ascend));
            } catch (const Error&) {
                continue;  // a turning or backward walk: no staircase fits it
            }
            JointSequence at_20 = resample_joints(s.motion, smpl22::kFps);
            place_on_floor(at_20);
            const MotionQuality q = score_motion(at_20);
            EXPECT_TRUE(quality_failures(q, default_quality_thresholds()).empty())
                << file << (ascend ? " up" : " down") << ": hover " << q.hover_m << " penetration " << q.penetration_m
                << " skate " << q.foot_skate_m_s;
            ++flights;
        }
    }
    std::printf("[shared walks] %zu walks, %d flights scored\n", walks.size(), flights);
    EXPECT_GE(flights, 40);
}

}  // namespace
}  // namespace t2imu
