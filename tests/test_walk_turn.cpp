// A walk turned onto a curve: the procedural walk (straight along +Z) turned 90 degrees left ends facing +X and
// travels that way, measured as a left turn of 90 degrees; a negative turn is a right one; frames before the turn
// are unchanged; a planted foot does not slide more than it did; and options that do not fit are refused.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "motion/foot_contacts.hpp"
#include "motion/motion_attributes.hpp"
#include "motion/skeleton.hpp"
#include "motion/walk_turn.hpp"
#include "walk_fixture.hpp"

using namespace t2imu;

namespace {

// The largest horizontal move (m) of a foot's ankle between two frames where it alone is planted in `source`.
double planted_slide(const JointSequence& m, const JointSequence& source) {
    double worst = 0;
    const std::vector<bool> left = planted_frames(source, Foot::left), right = planted_frames(source, Foot::right);
    for (Foot foot : {Foot::left, Foot::right}) {
        const std::vector<bool>& planted = foot == Foot::left ? left : right;
        const std::vector<bool>& other = foot == Foot::left ? right : left;
        const int ankle = foot == Foot::left ? smpl22::left_ankle : smpl22::right_ankle;
        for (int f = 1; f < m.num_frames; ++f)
            if (planted[static_cast<size_t>(f)] && planted[static_cast<size_t>(f - 1)] &&
                !other[static_cast<size_t>(f)]) {
                const Eigen::Vector3d d = m.at(f, ankle) - m.at(f - 1, ankle);
                worst = std::max(worst, std::hypot(d.x(), d.z()));
            }
    }
    return worst;
}

}  // namespace

TEST(WalkTurn, NinetyDegreesLeftIsMeasuredAsALeftTurnOfNinety) {
    const JointSequence walk = test::procedural_walk(8.0);
    WalkTurnOptions o;
    o.turn_rad = M_PI / 2, o.start_s = 2.0, o.duration_s = 2.0;
    const JointSequence turned = turn_walk(walk, o);
    const MotionAttributes a = measure_attributes(turned);
    EXPECT_NEAR(a.heading_change_deg, 90, 2);
    EXPECT_NEAR(a.path_turn_deg, 90, 10);
    EXPECT_EQ(a.travel, TravelDirection::forward);
    EXPECT_NEAR(a.ground_speed_m_s, 1.0, 0.05);
    for (int f = 0; f <= 40; ++f)  // before the turn nothing moves
        for (int k = 0; k < 22; ++k) ASSERT_LT((turned.at(f, k) - walk.at(f, k)).norm(), 1e-12);
    // Every bone keeps its length (each frame moves rigidly), and a foot alone on the ground slides no more than in the
    // walk.
    for (int f = 0; f < walk.num_frames; f += 7)
        for (int k = 1; k < 22; ++k) {
            const int p = smpl22::kParents[static_cast<size_t>(k)];
            EXPECT_NEAR((turned.at(f, k) - turned.at(f, p)).norm(), (walk.at(f, k) - walk.at(f, p)).norm(), 1e-9);
        }
    EXPECT_LT(planted_slide(turned, walk), planted_slide(walk, walk) + 0.005);
}

TEST(WalkTurn, ANegativeTurnTurnsRight) {
    WalkTurnOptions o;
    o.turn_rad = -2.5, o.start_s = 1.0, o.duration_s = 2.0;
    const MotionAttributes a = measure_attributes(turn_walk(test::procedural_walk(6.0), o));
    EXPECT_NEAR(a.heading_change_deg, -2.5 * 180 / M_PI, 3);
}

TEST(WalkTurn, RefusesATurnOutsideTheWalkOrLargerThanHalfACircle) {
    const JointSequence walk = test::procedural_walk(4.0);
    WalkTurnOptions o;
    o.start_s = 3.0, o.duration_s = 1.5;
    EXPECT_THROW(turn_walk(walk, o), Error);
    o.start_s = 1.0, o.turn_rad = 4.0;
    EXPECT_THROW(turn_walk(walk, o), Error);
    o.turn_rad = 1.0, o.duration_s = 0;
    EXPECT_THROW(turn_walk(walk, o), Error);
}
