#include "body/segments.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace t2imu {

using namespace smpl22;
using Eigen::Matrix3d;
using Eigen::Vector3d;

const std::array<SegmentDef, kNumJoints> kSegments = {{
    {spine1, -1, TwistRule::across_hips},                          // pelvis
    {left_knee, pelvis, TwistRule::bend, left_ankle, -1},          // left thigh: the shin folds backwards
    {right_knee, pelvis, TwistRule::bend, right_ankle, -1},        // right thigh
    {spine2, pelvis, TwistRule::across_hips},                      // spine1 (lower trunk)
    {left_ankle, left_hip, TwistRule::bend, left_foot, 1},         // left shin: the foot points forwards
    {right_ankle, right_hip, TwistRule::bend, right_foot, 1},      // right shin
    {spine3, spine1, TwistRule::across_trunk},                     // spine2 (middle trunk)
    {left_foot, left_knee, TwistRule::parent_swing},               // left foot
    {right_foot, right_knee, TwistRule::parent_swing},             // right foot
    {neck, spine2, TwistRule::across_shoulders},                   // spine3 (upper trunk)
    {-1, left_ankle, TwistRule::leaf},                             // left toes
    {-1, right_ankle, TwistRule::leaf},                            // right toes
    {head, spine3, TwistRule::parent_swing},                       // neck and head
    {left_shoulder, spine3, TwistRule::parent_swing},              // left collar
    {right_shoulder, spine3, TwistRule::parent_swing},             // right collar
    {-1, neck, TwistRule::leaf},                                   // head (rides on the neck)
    {left_elbow, left_collar, TwistRule::bend, left_wrist, 1},     // left upper arm: the forearm folds forwards
    {right_elbow, right_collar, TwistRule::bend, right_wrist, 1},  // right upper arm
    {left_wrist, left_shoulder, TwistRule::parent_swing},          // left forearm (elbow hinge)
    {right_wrist, right_shoulder, TwistRule::parent_swing},        // right forearm
    {-1, left_elbow, TwistRule::leaf},                             // left hand
    {-1, right_elbow, TwistRule::leaf},                            // right hand
}};

namespace {

Vector3d perpendicular(const Vector3d& a, const Vector3d& unit_l) { return a - a.dot(unit_l) * unit_l; }

Vector3d across(const Joints22& x, TwistRule rule) {
    const Vector3d hips = (x[left_hip] - x[right_hip]).normalized();
    const Vector3d shoulders = (x[left_shoulder] - x[right_shoulder]).normalized();
    if (rule == TwistRule::across_hips) return hips;
    if (rule == TwistRule::across_shoulders) return shoulders;
    return hips + shoulders;
}

// The twist reference a parent's orientation implies: its rest reference carried by R_parent, then swung
// by the shortest rotation from where R_parent puts the rest long axis to the actual long axis.
Vector3d swung_reference(const Matrix3d& parent, const Vector3d& rest_long, const Vector3d& rest_ref,
                         const Vector3d& l) {
    const Vector3d from = parent * rest_long;
    const Vector3d carried = parent * rest_ref;
    if (from.dot(l) < -0.9999) return carried;  // antiparallel: no unique swing; keep the carried reference
    return Eigen::Quaterniond::FromTwoVectors(from, l) * carried;
}

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

// Twist reference of segment s in one frame, given the parent's orientation already solved.
Vector3d twist_reference(int s, const Joints22& x, const Vector3d& l, const Matrix3d* parent, const RestAxes& rest) {
    const SegmentDef& d = kSegments[static_cast<size_t>(s)];
    if (d.rule == TwistRule::across_hips || d.rule == TwistRule::across_shoulders || d.rule == TwistRule::across_trunk)
        return across(x, d.rule);
    const Vector3d swing =
        swung_reference(*parent, rest.long_axis[static_cast<size_t>(s)], rest.twist_ref[static_cast<size_t>(s)], l);
    if (d.rule == TwistRule::parent_swing) return swing;
    const Vector3d beyond = x[static_cast<size_t>(d.bend_to)] - x[static_cast<size_t>(d.distal)];
    const Vector3d bend = perpendicular(beyond, l);
    const double norm = beyond.norm();
    const double sine = norm > 0 ? bend.norm() / norm : 0;  // sin of the bend angle
    const double w = smoothstep(std::sin(10 * M_PI / 180), std::sin(25 * M_PI / 180), sine);
    if (w == 0) return swing;
    const Vector3d b = d.bend_sign * bend.normalized();
    return w * b + (1 - w) * perpendicular(swing, l).normalized();
}

}  // namespace

void cross_section_axes(const Vector3d& l, Vector3d* front, Vector3d* side) {
    *front = perpendicular(Vector3d::UnitZ(), l).normalized();
    Vector3d v = perpendicular(perpendicular(Vector3d::UnitX(), l), *front);
    if (v.norm() < 0.3) v = perpendicular(perpendicular(Vector3d::UnitY(), l), *front);
    *side = v.normalized();
}

Matrix3d axis_frame(const Vector3d& l, const Vector3d& a) {
    Matrix3d f;
    const Vector3d e1 = l.normalized();
    const Vector3d e2 = perpendicular(a, e1).normalized();
    f.col(0) = e1;
    f.col(1) = e2;
    f.col(2) = e1.cross(e2);
    return f;
}

RestAxes rest_axes(const Joints22& rest) {
    RestAxes axes;
    for (int s = 0; s < kNumJoints; ++s) {
        const SegmentDef& d = kSegments[static_cast<size_t>(s)];
        const size_t i = static_cast<size_t>(s);
        if (d.rule == TwistRule::leaf) continue;  // filled from the parent below
        axes.long_axis[i] = (rest[static_cast<size_t>(d.distal)] - rest[i]).normalized();
        const bool trunk = d.rule == TwistRule::across_hips || d.rule == TwistRule::across_shoulders ||
                           d.rule == TwistRule::across_trunk;
        // Limbs and collars take the body's front as their rest reference; if a segment points forwards
        // (a foot), the part of "front" across it is its top side, still well defined.
        const Vector3d ref = trunk ? across(rest, d.rule) : Vector3d::UnitZ();
        axes.twist_ref[i] = perpendicular(ref, axes.long_axis[i]).normalized();
    }
    for (int s = 0; s < kNumJoints; ++s)
        if (kSegments[static_cast<size_t>(s)].rule == TwistRule::leaf) {
            const size_t p = static_cast<size_t>(kSegments[static_cast<size_t>(s)].parent);
            axes.long_axis[static_cast<size_t>(s)] = axes.long_axis[p];
            axes.twist_ref[static_cast<size_t>(s)] = axes.twist_ref[p];
        }
    return axes;
}

std::vector<Rotations22> segment_rotations(const std::vector<Joints22>& frames, const RestAxes& rest) {
    const size_t n = frames.size();
    std::vector<Rotations22> out(n);
    std::vector<Vector3d> refs(n), longs(n);
    // Segments in index order: every parent index is smaller than its child's in SMPL-22.
    for (int s = 0; s < kNumJoints; ++s) {
        const size_t i = static_cast<size_t>(s);
        const SegmentDef& d = kSegments[i];
        if (d.rule == TwistRule::leaf) {
            for (size_t f = 0; f < n; ++f) out[f][i] = out[f][static_cast<size_t>(d.parent)];
            continue;
        }
        for (size_t f = 0; f < n; ++f) {
            longs[f] = frames[f][static_cast<size_t>(d.distal)] - frames[f][i];
            const Matrix3d* parent = d.parent >= 0 ? &out[f][static_cast<size_t>(d.parent)] : nullptr;
            refs[f] = twist_reference(s, frames[f], longs[f].normalized(), parent, rest);
        }
        const Matrix3d rest_frame = axis_frame(rest.long_axis[i], rest.twist_ref[i]);
        for (size_t f = 0; f < n; ++f) out[f][i] = axis_frame(longs[f], refs[f]) * rest_frame.transpose();
    }
    return out;
}

}  // namespace t2imu
