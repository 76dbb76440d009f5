// The interface every body offers the sensor stage: a rest shape with the SMPL-22 skeleton, points with
// outward normals on its surface, and where such a point goes when the body is posed.
//
// Frames: rest body coordinates are metres, Y up, the body facing +Z, its left side at +X, soles at y = 0,
// standing upright with the arms hanging (procedural) or in the model's own rest pose (SMPL's T-pose).
// A posed frame gives every segment's orientation R (world from rest, see segments.hpp) and joint positions.
#pragma once
#include <Eigen/Core>
#include <memory>
#include <string>

#include "body/body_spec.hpp"
#include "body/segments.hpp"

namespace t2imu {

struct SurfacePoint {
    Eigen::Vector3d position;  // rest body coordinates, m
    Eigen::Vector3d normal;    // unit outward normal, rest body coordinates
};

struct PosedFrame {
    Joints22 joints;       // world, m
    Rotations22 rotation;  // per segment, world from rest
};

// Where a sensor sits: on a segment (rigid with it) or on an SMPL vertex (skinned).
struct BodyAnchor {
    int segment = 0;                                          // proximal joint of the segment
    int vertex = -1;                                          // >= 0: an SMPL vertex
    Eigen::Vector3d rest_position = Eigen::Vector3d::Zero();  // rest body coordinates, m
};

class BodyModel {
public:
    virtual ~BodyModel() = default;
    virtual const BodySpec& spec() const = 0;
    virtual const Joints22& rest_joints() const = 0;
    // The skin point of `segment` at `along` (0 = proximal joint, 1 = distal joint) and `around` (radians
    // about the long axis: 0 at the segment's front, +pi/2 towards the body's left; see procedural_body.hpp).
    virtual SurfacePoint surface_point(int segment, double along, double around) const = 0;
    // A skin vertex of a mesh body (SMPL); bodies without vertices refuse.
    virtual SurfacePoint vertex_point(int vertex) const = 0;
    // The anchor for a surface point of a segment (procedural: the segment; SMPL: the nearest skin vertex).
    virtual BodyAnchor anchor(int segment, const SurfacePoint& p) const = 0;
    // Posed position (world, m) and the rotation (world from rest) that carries the anchor's rest frame.
    virtual void pose_anchor(const BodyAnchor& a, const PosedFrame& frame, Eigen::Vector3d* position,
                             Eigen::Matrix3d* rotation) const = 0;
};

// Builds the body a spec names (procedural or SMPL). Kind::none has no body of its own: the caller makes a
// procedural one sized to the input motion (fitting.hpp).
std::unique_ptr<BodyModel> make_body(const BodySpec& spec);

}  // namespace t2imu
