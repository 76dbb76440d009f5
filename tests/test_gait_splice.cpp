// Two walks joined at a stance of one foot: a procedural level walk (each foot planted for 60 % of its 1 s cycle)
// with itself, turned, and its stairs up with its stairs down, where the geometry is known exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "motion/foot_contacts.hpp"
#include "motion/gait_splice.hpp"
#include "motion/motion_edit.hpp"
#include "motion/skeleton.hpp"
#include "motion/stair_gait.hpp"
#include "walk_fixture.hpp"

namespace t2imu {
namespace {

using Eigen::Vector3d;
using namespace smpl22;
using test::procedural_walk;

// `m` turned by `angle` about the vertical through the origin and moved by `shift`.
JointSequence moved(JointSequence m, double angle, const Vector3d& shift) {
    const double c = std::cos(angle), s = std::sin(angle);
    for (Vector3d& p : m.positions) p = Vector3d(c * p.x() - s * p.z(), p.y(), s * p.x() + c * p.z()) + shift;
    return m;
}

// The largest distance any joint moves between two frames of [begin, end) (m).
double largest_step(const JointSequence& m, int begin, int end) {
    double most = 0;
    for (int f = std::max(1, begin); f < end; ++f)
        for (int j = 0; j < m.num_joints; ++j) most = std::max(most, (m.at(f, j) - m.at(f - 1, j)).norm());
    return most;
}

// The fixture walk's 8 s turned into a flight up and a flight down, 0.17 m rises.
std::pair<JointSequence, JointSequence> flights_up_and_down() {
    const JointSequence walk = procedural_walk(8.0);
    StairOptions up = default_stair_options(true), down = default_stair_options(false);
    up.rise_m = down.rise_m = 0.17;
    return {derive_stairs(walk, up).motion, derive_stairs(walk, down).motion};
}

TEST(GaitSplice, AWalkJoinedToItselfTurnedAndMovedWalksOnWithoutAJump) {
    const JointSequence walk = procedural_walk(4.0);
    // The second walk starts 5 m away, facing 90 deg off: the splice must undo both.
    const JointSequence other = moved(walk, M_PI / 2, Vector3d(5, 0.3, -2));
    const GaitSplice s = splice_at_stance(walk, other, GaitSpliceOptions{});
    // A joint moves at most what it moves in one frame of the source walk (feet swing at up to 2.5 m/s), plus
    // the blend's share: within 10 %.
    const double source = largest_step(walk, 0, walk.num_frames);
    EXPECT_LT(largest_step(s.motion, 0, s.motion.num_frames), 1.1 * source);
    // It still walks along +Z on the floor: the heights of the walk, and the body faces +Z at the end.
    EXPECT_NEAR(s.motion.at(s.motion.num_frames - 1, pelvis).y(), walk.at(0, pelvis).y(), 1e-6);
    EXPECT_NEAR(body_facing(s.motion, s.motion.num_frames - 1).z(), 1.0, 1e-6);
    EXPECT_LT(max_bone_length_error(s.motion, bone_lengths(walk, 0)), 1e-6);
    EXPECT_GT(s.motion.at(s.motion.num_frames - 1, pelvis).z(), walk.at(walk.num_frames - 1, pelvis).z());
}

TEST(GaitSplice, ThePlantedFootStaysWhereItStandsThroughTheBlend) {
    const JointSequence walk = procedural_walk(4.0);
    const GaitSpliceOptions o{0.3};
    const GaitSplice s = splice_at_stance(walk, moved(walk, 0.4, Vector3d(1, 0, 1)), o);
    const int half = frames_of(o.blend_s / 2, walk.fps);
    // One foot is planted over the whole blend window: its ankle does not move (the fixture's feet stand still).
    double left = 0, right = 0;
    for (int f = s.splice_frame - half; f <= s.splice_frame + half; ++f) {
        left = std::max(left, (s.motion.at(f, left_ankle) - s.motion.at(s.splice_frame, left_ankle)).norm());
        right = std::max(right, (s.motion.at(f, right_ankle) - s.motion.at(s.splice_frame, right_ankle)).norm());
    }
    EXPECT_LT(std::min(left, right), 1e-6);
}

TEST(GaitSplice, UpAFlightAndDownTheNextRisesThenFallsByTheFlights) {
    const auto [a, b] = flights_up_and_down();
    const GaitSplice s = splice_at_stance(a, b, GaitSpliceOptions{});
    const double start = s.motion.at(0, pelvis).y(), end = s.motion.at(s.motion.num_frames - 1, pelvis).y();
    double top = -1e9;
    for (int f = 0; f < s.motion.num_frames; ++f) top = std::max(top, s.motion.at(f, pelvis).y());
    // The pelvis climbs what the up flight climbs (within one rise: it is cut at mid-stance on the landing, at least
    // 2 m) and then falls what the down flight falls less its steps before the splice: the first stance of the
    // splicing foot that the flight holds whole, at most three rises in.
    const auto height = [](const JointSequence& m, int f) { return m.at(f, pelvis).y(); };
    const double climb = height(a, a.num_frames - 1) - height(a, 0);
    EXPECT_GT(climb, 2.0);
    EXPECT_NEAR(top - start, climb, 0.17);
    const double fall = height(b, 0) - height(b, b.num_frames - 1);
    EXPECT_GT(top - end, fall - 3 * 0.17);
    EXPECT_LT(top - end, fall + 0.17);
    EXPECT_LT(largest_step(s.motion, 0, s.motion.num_frames),
              1.1 * std::max(largest_step(a, 0, a.num_frames), largest_step(b, 0, b.num_frames)));
}

TEST(GaitSplice, ARoundTripCutToLengthKeepsTheJoinAtItsMiddle) {
    const auto [a, b] = flights_up_and_down();
    const GaitSplice whole = splice_at_stance(a, b, GaitSpliceOptions{});
    const int frames = 120;  // 6 s at 20 fps, well inside the join's length
    ASSERT_GT(whole.splice_frame - frames / 2, 0);
    ASSERT_GT(whole.motion.num_frames - whole.splice_frame, frames / 2);
    const GaitSplice cut = splice_to_length(a, b, frames, GaitSpliceOptions{});
    ASSERT_EQ(cut.motion.num_frames, frames);
    EXPECT_EQ(cut.splice_frame, frames / 2);
    // The window is the join's frames around the splice, untouched.
    const int begin = whole.splice_frame - frames / 2;
    for (int f = 0; f < frames; ++f)
        EXPECT_LT((cut.motion.at(f, pelvis) - whole.motion.at(begin + f, pelvis)).norm(), 1e-12) << f;
    // Asked for more than the join holds, it keeps as much of the shorter side as there is.
    const int longer = whole.motion.num_frames - 2;
    const GaitSplice most = splice_to_length(a, b, longer, GaitSpliceOptions{});
    EXPECT_EQ(most.motion.num_frames, longer);
    EXPECT_LT((most.motion.at(most.splice_frame, pelvis) - whole.motion.at(whole.splice_frame, pelvis)).norm(), 1e-12);
    try {
        splice_to_length(a, b, whole.motion.num_frames + 1, GaitSpliceOptions{});
        FAIL() << "a window longer than the join was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("frames"), std::string::npos) << e.what();
    }
}

// A whole body flickering up and down at 5 Hz (2 cm for two frames, -2 cm for two: a sampled motion's flicker) moves
// every planted foot at up to 0.57 m/s vertically: no stance to join at, unless the stances are looked for on the
// smoothed joints (a Gaussian of one frame keeps 0.29 of a 5 Hz sine).
TEST(GaitSplice, StancesUnderAFrameToFrameFlickerAreFoundOnTheSmoothedJoints) {
    auto [a, b] = flights_up_and_down();
    for (JointSequence* m : {&a, &b})
        for (int f = 0; f < m->num_frames; ++f)
            for (int j = 0; j < m->num_joints; ++j) m->at(f, j).y() += (f / 2) % 2 ? 0.02 : -0.02;
    EXPECT_THROW(splice_at_stance(a, b, GaitSpliceOptions{}), Error);
    GaitSpliceOptions smoothed;
    smoothed.contact_smoothing_s = 0.05;
    const GaitSplice s = splice_at_stance(a, b, smoothed);
    // Joined unsmoothed: the frames before the blend are `a`'s own, flicker and all.
    for (int f = 0; f < s.splice_frame - frames_of(smoothed.blend_s / 2, a.fps); ++f)
        EXPECT_LT((s.motion.at(f, pelvis) - a.at(f, pelvis)).norm(), 1e-6) << f;
    smoothed.contact_smoothing_s = 0.2;
    try {
        splice_at_stance(a, b, smoothed);
        FAIL() << "a smoothing of 0.2 s was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("contact_smoothing_s"), std::string::npos) << e.what();
    }
}

TEST(GaitSplice, RefusesBadOptionsAndMotionsWithoutAStanceNamingTheField) {
    const JointSequence walk = procedural_walk(4.0);
    try {
        splice_at_stance(walk, walk, GaitSpliceOptions{0.01});
        FAIL() << "a blend of 0.01 s was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("blend_s"), std::string::npos) << e.what();
    }
    // A body sliding along at 2 m/s never plants a foot.
    JointSequence sliding = walk;
    for (int f = 0; f < sliding.num_frames; ++f)
        for (int j = 0; j < kNumJoints; ++j) sliding.at(f, j) = walk.at(0, j) + Vector3d(0, 0, 2.0 * f / walk.fps);
    EXPECT_THROW(splice_at_stance(walk, sliding, GaitSpliceOptions{}), Error);
    EXPECT_THROW(splice_at_stance(sliding, walk, GaitSpliceOptions{}), Error);
    JointSequence other_rate = walk;
    other_rate.fps = 30;
    EXPECT_THROW(splice_at_stance(walk, other_rate, GaitSpliceOptions{}), Error);
}

}  // namespace
}  // namespace t2imu
