// The 22 body segments of the SMPL-22 skeleton and how their orientations follow from joint positions.
//
// A segment is named after its proximal joint, as in SMPL, where joint k's rotation moves the bones to its
// children: "left_hip" is the thigh (hip -> knee), "left_knee" the shin, "left_shoulder" the upper arm,
// "left_elbow" the forearm, "neck" the head and neck. Leaf joints (feet, head, wrists) ride on their parent.
//
// Joint positions fix a segment's long axis but not its twist about it. The twist comes from a neighbouring
// bone, as a physiotherapist would read it off a skeleton:
//   - trunk: the line through the hips (pelvis, spine1), the shoulders (spine3), or their mean (spine2);
//   - thigh, upper arm: the plane in which the knee or elbow bends (a hinge bends in one plane only);
//   - shin: the direction the foot points;
//   - forearm, foot, collar, neck: the parent's orientation carried over by the smallest rotation that aligns
//     the long axes ("swing" without twist), which for the forearm is exactly the elbow hinge.
// Where a limb is nearly straight its bend plane is undefined, so the bend twist is blended smoothly into the
// swing rule between 10 and 25 degrees of bend: no jumps when an arm straightens.
//
// A segment's orientation R (world from rest) maps the rest body (standing, facing +Z, Y up, left = +X) onto
// the posed one: R = F(posed) F(rest)^T, where F(l, a) is the orthonormal frame [l, a_perp, l x a_perp] of the
// long axis l and the twist reference a. Rest directions are the body's own, so R = I in the rest pose.
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

#include "motion/skeleton.hpp"

namespace t2imu {

using Joints22 = std::array<Eigen::Vector3d, smpl22::kNumJoints>;
using Rotations22 = std::array<Eigen::Matrix3d, smpl22::kNumJoints>;

enum class TwistRule { across_hips, across_trunk, across_shoulders, bend, parent_swing, leaf };

struct SegmentDef {
    int distal;  // the joint the long axis points to (-1 for a leaf)
    int parent;  // parent segment (-1 for the pelvis)
    TwistRule rule;
    int bend_to = -1;      // TwistRule::bend: the joint past `distal` whose offset shows the bend
    double bend_sign = 1;  // +1 when the bend points to the segment's front at rest, -1 to its back (knee)
};
extern const std::array<SegmentDef, smpl22::kNumJoints> kSegments;  // indexed by proximal joint

// The rest long axis and twist reference of every segment (unit vectors, rest body coordinates).
struct RestAxes {
    std::array<Eigen::Vector3d, smpl22::kNumJoints> long_axis, twist_ref;
};
RestAxes rest_axes(const Joints22& rest);

// Orientations of all segments over a motion (world from rest), frames[f].
std::vector<Rotations22> segment_rotations(const std::vector<Joints22>& frames, const RestAxes& rest);

// Directions across a segment whose long axis is the unit vector l (rest coordinates): `front` is +Z made
// perpendicular to l; `side` is +X (the body's left) made perpendicular to both, or +Y (up) for a segment that
// runs sideways (the collars). Angles about a segment are measured from front towards side.
void cross_section_axes(const Eigen::Vector3d& l, Eigen::Vector3d* front, Eigen::Vector3d* side);

// The frame [l, a_perp, l x a_perp] (columns); a must not be parallel to l.
Eigen::Matrix3d axis_frame(const Eigen::Vector3d& l, const Eigen::Vector3d& a);

}  // namespace t2imu
