// Two-bone IK against geometry with known answers: reachable targets land exactly with both lengths kept, the
// knee bends to the hint's side, and out-of-reach targets give the straight or folded chain.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "motion/two_bone_ik.hpp"

namespace t2imu {
namespace {

using Eigen::Vector3d;

TEST(TwoBoneIk, ReachesAReachableTargetWithBothLengthsKept) {
    const Vector3d hip(0.1, 0.9, 0.0), ankle(0.12, 0.15, 0.3), hint = hip + Vector3d(0, -0.4, 0.5);
    const TwoBoneIkResult r = solve_two_bone_ik(hip, ankle, 0.39, 0.43, hint);
    EXPECT_TRUE(r.reached);
    EXPECT_NEAR((r.end - ankle).norm(), 0.0, 1e-12);
    EXPECT_NEAR((r.middle - hip).norm(), 0.39, 1e-9);
    EXPECT_NEAR((r.middle - ankle).norm(), 0.43, 1e-9);
}

TEST(TwoBoneIk, ARightAngledChainHasItsKneeAtTheCorner) {
    // Hip at the origin, ankle at (0, -0.4, 0.3): with 0.4 and 0.3 bones the knee bends 90 deg at (0, -0.4, 0)
    // or (0, 0, 0.3); a hint behind and below picks the first, one in front and above the second.
    const Vector3d hip(0, 0, 0), ankle(0, -0.4, 0.3);
    const TwoBoneIkResult below = solve_two_bone_ik(hip, ankle, 0.4, 0.3, Vector3d(0, -1, -1));
    EXPECT_NEAR((below.middle - Vector3d(0, -0.4, 0)).norm(), 0.0, 1e-12);
    const TwoBoneIkResult above = solve_two_bone_ik(hip, ankle, 0.3, 0.4, Vector3d(0, 1, 1));
    EXPECT_NEAR((above.middle - Vector3d(0, 0, 0.3)).norm(), 0.0, 1e-12);
}

TEST(TwoBoneIk, TheKneeBendsToTheHintsSide) {
    const Vector3d hip(0, 1, 0), ankle(0, 0.2, 0.1);
    for (const Vector3d& side : {Vector3d(0, 0, 1), Vector3d(0, 0, -1), Vector3d(1, 0, 0)}) {
        const TwoBoneIkResult r = solve_two_bone_ik(hip, ankle, 0.45, 0.45, hip + 0.4 * (ankle - hip) + side);
        const Vector3d axis = (ankle - hip).normalized();
        const Vector3d off_axis = (r.middle - hip) - (r.middle - hip).dot(axis) * axis;
        EXPECT_GT(off_axis.normalized().dot((side - side.dot(axis) * axis).normalized()), 1 - 1e-12);
    }
}

TEST(TwoBoneIk, AnOutOfReachTargetStretchesTheChainStraightTowardIt) {
    const Vector3d hip(0, 1, 0), target(0, -0.2, 0.5);  // 1.3 m away, bones 0.4 + 0.45
    const TwoBoneIkResult r = solve_two_bone_ik(hip, target, 0.4, 0.45, Vector3d(0, 0, 1));
    EXPECT_FALSE(r.reached);
    const Vector3d dir = (target - hip).normalized();
    EXPECT_NEAR((r.middle - (hip + 0.4 * dir)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((r.end - (hip + 0.85 * dir)).norm(), 0.0, 1e-12);
}

TEST(TwoBoneIk, ATargetTooNearFoldsTheChainFlat) {
    const Vector3d hip(0, 1, 0), target(0, 0.95, 0);  // 0.05 m away, bones differ by 0.1
    const TwoBoneIkResult r = solve_two_bone_ik(hip, target, 0.5, 0.4, Vector3d(0, 0, 1));
    EXPECT_FALSE(r.reached);
    EXPECT_NEAR((r.end - Vector3d(0, 0.9, 0)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((r.middle - hip).norm(), 0.5, 1e-12);
    EXPECT_NEAR((r.middle - r.end).norm(), 0.4, 1e-12);
}

TEST(TwoBoneIk, AHintOnTheLineStillBendsWithLengthsKept) {
    const Vector3d hip(0, 1, 0), ankle(0, 0.3, 0);
    const TwoBoneIkResult r = solve_two_bone_ik(hip, ankle, 0.4, 0.4, Vector3d(0, 0.5, 0));
    EXPECT_TRUE(r.reached);
    EXPECT_NEAR((r.middle - hip).norm(), 0.4, 1e-12);
    EXPECT_NEAR((r.middle - ankle).norm(), 0.4, 1e-12);
}

TEST(TwoBoneIk, RefusesANonPositiveLength) {
    EXPECT_THROW(solve_two_bone_ik(Vector3d::Zero(), Vector3d::UnitX(), 0.0, 1.0, Vector3d::UnitY()), Error);
}

}  // namespace
}  // namespace t2imu
