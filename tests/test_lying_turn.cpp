// Turning onto the side and back while lying, on a supine pose built from HumanML3D's target skeleton: the turn's
// angle, its axis, the floor contact and the return are known.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/error.hpp"
#include "motion/lying_turn.hpp"
#include "motion/motion_edit.hpp"
#include "motion/motion_quality.hpp"
#include "motion/skeleton.hpp"
#include "test_util.hpp"

namespace t2imu {
namespace {

using Eigen::Vector3d;
using namespace smpl22;

// The rest pose turned -90 deg about X (head toward -Z, face up), pelvis 0.1 m above the floor, held `frames`.
JointSequence supine_hold(int frames) {
    JointSequence m(frames, kNumJoints, kFps);
    const Eigen::Matrix3d supine = Eigen::AngleAxisd(-test::kPi / 2, Vector3d::UnitX()).toRotationMatrix();
    for (int f = 0; f < frames; ++f) {
        m.at(f, pelvis) = Vector3d(0, 0.1, 0);
        for (int j = 1; j < kNumJoints; ++j)
            m.at(f, j) = m.at(f, kParents[static_cast<size_t>(j)]) + supine * kTargetOffsets[static_cast<size_t>(j)];
    }
    return m;
}

double lowest_joint(const JointSequence& m, int f) {
    double y = m.at(f, 0).y();
    for (int j = 1; j < kNumJoints; ++j) y = std::min(y, m.at(f, j).y());
    return y;
}

TEST(LyingTurn, TurnsAboutTheLongAxisByTheAngleAndComesBack) {
    LyingTurnOptions o;  // 1.5 s before, 1.5 turning, 2 on the side, 1.5 back, 1.5 after: 161 frames at 20 fps
    const JointSequence src = supine_hold(200);
    const JointSequence m = lying_turn(src, o);
    ASSERT_EQ(m.num_frames, 161);
    EXPECT_LT(max_bone_length_error(m, bone_lengths(src, 0)), 1e-9);  // rigid
    const int side = 80;                                              // 4 s: on the side
    const Vector3d across0 = src.at(0, left_hip) - src.at(0, right_hip),
                   across = m.at(side, left_hip) - m.at(side, right_hip);
    EXPECT_NEAR(std::acos(across0.normalized().dot(across.normalized())), o.angle_rad, 1e-9);
    // About the long axis: the line from pelvis to neck keeps its direction.
    const Vector3d along0 = src.at(0, neck) - src.at(0, pelvis), along = m.at(side, neck) - m.at(side, pelvis);
    EXPECT_NEAR(along0.normalized().dot(along.normalized()), 1.0, 1e-12);
    // Right-handed about the head-ward axis (-Z): the left hip (+X) goes down toward the floor, the right up.
    EXPECT_LT(m.at(side, left_hip).y(), m.at(side, right_hip).y());
    // Before and after the turn (and the lift's envelope, 0.5 s either side) the body lies as the source lies.
    for (int f : {0, 19, 141, 160}) EXPECT_LT((m.at(f, head) - src.at(f, head)).norm(), 1e-9) << "frame " << f;
}

TEST(LyingTurn, TheBodyRestsOnTheFloorContactAndTheSideLiesHigher) {
    const JointSequence src = supine_hold(200);
    const JointSequence m = lying_turn(src, LyingTurnOptions{});
    const double contact = lowest_joint(src, 0);
    double lowest = 1e9;
    for (int f = 0; f < m.num_frames; ++f) {
        EXPECT_GE(lowest_joint(m, f), contact - 1e-9) << "frame " << f;
        lowest = std::min(lowest, lowest_joint(m, f));
    }
    EXPECT_NEAR(lowest, contact, 1e-9);
    EXPECT_NEAR(lowest_joint(m, 80), contact, 0.01);                 // on the side it rests on the floor, not above it
    EXPECT_GT(m.at(80, pelvis).y(), src.at(80, pelvis).y() + 0.05);  // the hip's half width above the sacrum's
    EXPECT_TRUE(quality_failures(score_motion(m), default_quality_thresholds()).empty());
}

TEST(LyingTurn, RefusesBadOptionsAndSourcesNamingTheField) {
    LyingTurnOptions o;
    o.angle_rad = 0.3;
    try {
        lying_turn(supine_hold(200), o);
        FAIL() << "accepted a 0.3 rad turn";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("angle_rad"), std::string::npos) << e.what();
    }
    EXPECT_THROW(lying_turn(supine_hold(100), LyingTurnOptions{}), Error);  // shorter than the timeline
    JointSequence standing = supine_hold(200);
    const Eigen::Matrix3d up = Eigen::AngleAxisd(test::kPi / 2, Vector3d::UnitX()).toRotationMatrix();
    for (int f = 0; f < standing.num_frames; ++f)
        for (int j = 0; j < kNumJoints; ++j)
            standing.at(f, j) = Vector3d(0, 0.9, 0) + up * (standing.at(f, j) - Vector3d(0, 0.1, 0));
    EXPECT_THROW(lying_turn(standing, LyingTurnOptions{}), Error);
}

}  // namespace
}  // namespace t2imu
