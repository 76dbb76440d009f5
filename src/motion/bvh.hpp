// BVH motion capture files (Biovision Hierarchy): a joint tree with rest offsets and channels, then one line of
// channel values per frame. Any channel order and rotation order, any number of joints; positions channels may
// appear on any joint (some exporters animate every joint's translation). Rotations are Euler angles in degrees
// composed in the order the channels are listed (R = R_c1 R_c2 R_c3), applied to the child frame.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "motion/quaternion.hpp"

namespace t2imu {

enum class BvhChannel { x_position, y_position, z_position, x_rotation, y_rotation, z_rotation };

struct BvhJoint {
    std::string name;        // End Sites are named "<parent>/end"
    int parent = -1;         // index into BvhMotion::joints, -1 for the root
    Eigen::Vector3d offset;  // rest translation from the parent, file units
    std::vector<BvhChannel> channels;
    int first_channel = 0;  // index of this joint's first value in a frame line
    bool end_site = false;
};

struct BvhMotion {
    std::vector<BvhJoint> joints;  // parents before children
    int num_channels = 0;
    int num_frames = 0;
    double frame_time = 0;       // seconds
    std::vector<double> values;  // [num_frames * num_channels]

    int find(const std::string& name) const;  // -1 when absent
    const double* frame(int f) const {
        return values.data() + static_cast<size_t>(f) * static_cast<size_t>(num_channels);
    }
};

// One frame's local transforms: rotation and translation of each joint relative to its parent (file units).
struct BvhPose {
    std::vector<Quat> rotation;
    std::vector<Eigen::Vector3d> translation;
};

BvhMotion parse_bvh(const std::string& text, const std::string& source);
BvhMotion read_bvh(const std::string& path);
// Depth-first, whatever the order of `joints`; 6 decimals, LF line ends.
std::string format_bvh(const BvhMotion& motion);

// How a joint's position channels combine with its OFFSET. Exporters differ and the file does not say:
//   replace_offset     the channels are the joint's whole translation from its parent (most exporters)
//   add_to_offset      the channels are a displacement added to OFFSET (iClone)
//   root_only          the root's channels add to its OFFSET; every other joint keeps its OFFSET (ReActIdle's
//                      Blender/Rigify export: non-root channels equal OFFSET in every frame but the thighs',
//                      which drift by 1-2 cm, a hip joint sliding in the pelvis that no rigid skeleton has; the
//                      root's channels are centimetre-scale sway while its OFFSET holds the pelvis height)
enum class PositionChannels { replace_offset, add_to_offset, root_only };
BvhPose bvh_pose(const BvhMotion& motion, int frame, PositionChannels positions = PositionChannels::replace_offset);
// World positions of every joint (End Sites included), file units and axes.
std::vector<Eigen::Vector3d> bvh_forward_kinematics(const BvhMotion& motion, const BvhPose& pose);
// Interpolates two poses: slerp of rotations, linear translations; a in [0, 1].
BvhPose interpolate_pose(const BvhPose& p0, const BvhPose& p1, double a);

}  // namespace t2imu
