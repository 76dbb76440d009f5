// Segment orientations from joint positions: identity in the rest pose, a rigid turn of the whole body for every
// segment, long axes carried onto the posed bones, a hip flexed 90 deg with the knee bent (thigh = Rx(-90),
// shin unturned), orthonormal frames and cross-section axes.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "body/segments.hpp"

using namespace t2imu;
using namespace t2imu::smpl22;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {
// Standing, facing +Z, left at +X, arms hanging with the elbows very slightly bent forwards.
Joints22 standing() {
    Joints22 p;
    p[pelvis] = {0, 0.9, 0};
    p[spine1] = {0, 1.0, -0.01};
    p[spine2] = {0, 1.15, -0.01};
    p[spine3] = {0, 1.25, 0};
    p[neck] = {0, 1.45, 0};
    p[head] = {0, 1.6, 0.02};
    for (int side : {-1, 1}) {
        const bool left = side > 0;
        p[left ? left_hip : right_hip] = {0.1 * side, 0.85, 0};
        p[left ? left_knee : right_knee] = {0.1 * side, 0.47, 0};
        p[left ? left_ankle : right_ankle] = {0.1 * side, 0.08, 0};
        p[left ? left_foot : right_foot] = {0.1 * side, 0.02, 0.14};
        p[left ? left_collar : right_collar] = {0.07 * side, 1.35, 0};
        p[left ? left_shoulder : right_shoulder] = {0.19 * side, 1.37, 0};
        p[left ? left_elbow : right_elbow] = {0.21 * side, 1.08, 0};
        p[left ? left_wrist : right_wrist] = {0.22 * side, 0.83, 0.02};
    }
    return p;
}

double distance(const Matrix3d& a, const Matrix3d& b) { return (a - b).norm(); }
}  // namespace

TEST(Segments, RestPoseGivesIdentity) {
    const Joints22 rest = standing();
    const std::vector<Rotations22> r = segment_rotations({rest}, rest_axes(rest));
    for (int s = 0; s < kNumJoints; ++s) EXPECT_LT(distance(r[0][s], Matrix3d::Identity()), 1e-12) << kJointNames[s];
}

TEST(Segments, ARigidTurnTurnsEverySegment) {
    const Joints22 rest = standing();
    const Matrix3d q =
        (Eigen::AngleAxisd(1.1, Vector3d::UnitY()) * Eigen::AngleAxisd(0.3, Vector3d(1, 0, 1).normalized()))
            .toRotationMatrix();
    Joints22 moved;
    for (int k = 0; k < kNumJoints; ++k) moved[k] = q * rest[k] + Vector3d(2, 0.1, -3);
    const std::vector<Rotations22> r = segment_rotations({moved}, rest_axes(rest));
    for (int s = 0; s < kNumJoints; ++s) EXPECT_LT(distance(r[0][s], q), 1e-12) << kJointNames[s];
}

TEST(Segments, HipFlexedNinetyDegreesWithTheKneeBent) {
    // The left thigh points forwards (+Z), the shin hangs down from the knee, the foot points forwards: the thigh
    // is turned -90 deg about X (rest long axis (0,-1,0) -> (0,0,1), bend reference (0,0,1) -> (0,1,0)); the shin
    // and foot keep their rest orientation.
    const Joints22 rest = standing();
    Joints22 p = rest;
    const double thigh = (rest[left_hip] - rest[left_knee]).norm();
    p[left_knee] = rest[left_hip] + Vector3d(0, 0, thigh);
    const Vector3d shift = p[left_knee] - rest[left_knee];
    p[left_ankle] = rest[left_ankle] + shift;
    p[left_foot] = rest[left_foot] + shift;
    const RestAxes axes = rest_axes(rest);
    const Rotations22 r = segment_rotations({p}, axes)[0];
    EXPECT_LT(distance(r[left_hip], Eigen::AngleAxisd(-M_PI / 2, Vector3d::UnitX()).toRotationMatrix()), 1e-12);
    EXPECT_LT(distance(r[left_knee], Matrix3d::Identity()), 1e-12);
    EXPECT_LT(distance(r[left_ankle], Matrix3d::Identity()), 1e-12);
    EXPECT_LT(distance(r[left_foot], Matrix3d::Identity()), 1e-12);  // a leaf rides on its parent
    // The right leg did not move.
    EXPECT_LT(distance(r[right_hip], Matrix3d::Identity()), 1e-12);
    // Every segment's rotation carries its rest long axis onto the posed bone.
    for (int s = 0; s < kNumJoints; ++s) {
        const int distal = kSegments[s].distal;
        if (distal < 0) continue;
        const Vector3d bone = (p[distal] - p[s]).normalized();
        EXPECT_LT((r[s] * axes.long_axis[s] - bone).norm(), 1e-12) << kJointNames[s];
    }
}

TEST(Segments, RestAxesAreUnitAndPerpendicular) {
    const RestAxes a = rest_axes(standing());
    for (int s = 0; s < kNumJoints; ++s) {
        EXPECT_NEAR(a.long_axis[s].norm(), 1.0, 1e-12);
        EXPECT_NEAR(a.twist_ref[s].norm(), 1.0, 1e-12);
        EXPECT_NEAR(a.long_axis[s].dot(a.twist_ref[s]), 0.0, 1e-12);
    }
    // The thigh points down; a foot's leaf (toes) shares the foot's axes.
    EXPECT_LT((a.long_axis[left_hip] - Vector3d(0, -1, 0)).norm(), 1e-12);
    EXPECT_EQ(a.long_axis[left_foot], a.long_axis[left_ankle]);
    // The pelvis's twist reference is the line through the hips (towards the left, +X).
    EXPECT_LT((a.twist_ref[pelvis] - Vector3d(1, 0, 0)).norm(), 1e-12);
}

TEST(Segments, AxisFrameAndCrossSectionAxes) {
    const Matrix3d f = axis_frame(Vector3d(0, -2, 0), Vector3d(0.3, 0.5, 1));
    EXPECT_LT((f.transpose() * f - Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_NEAR(f.determinant(), 1.0, 1e-12);
    EXPECT_LT((f.col(0) - Vector3d(0, -1, 0)).norm(), 1e-15);
    EXPECT_LT((f.col(1) - Vector3d(0.3, 0, 1).normalized()).norm(), 1e-12);
    Vector3d front, side;
    cross_section_axes(Vector3d(0, -1, 0), &front, &side);  // a hanging limb: front +Z, side +X
    EXPECT_LT((front - Vector3d::UnitZ()).norm(), 1e-12);
    EXPECT_LT((side - Vector3d::UnitX()).norm(), 1e-12);
    cross_section_axes(Vector3d(1, 0, 0), &front, &side);  // a sideways collar: side is up
    EXPECT_LT((front - Vector3d::UnitZ()).norm(), 1e-12);
    EXPECT_LT((side - Vector3d::UnitY()).norm(), 1e-12);
}
