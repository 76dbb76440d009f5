// Acclaim ASF (skeleton) and AMC (motion) files, as CMU and HDM05 publish them.
//
// ASF conventions: each bone has a direction (unit vector, world frame of the rest pose), a length, an `axis`
// (Euler angles, degrees, of the bone's local frame C) and its degrees of freedom. A bone's world rotation is
// W = W_parent C M C^-1, with M the AMC rotation of the frame (R = Rz Ry Rx of the rx, ry, rz values), and its
// end point is its start plus W (direction x length). Lengths and root translations are in ASF units:
// `:units length L` means one unit is 1/L inches, so metres = units x 0.0254 / L.
//
// Here the skeleton is held in the BVH structures: one joint per bone, at the bone's START (named after the
// bone), whose children sit at offset direction x length; the End Site of a leaf bone is its end point. So the
// joint "lfemur" is the hip, "ltibia" the knee.
#pragma once
#include <string>
#include <vector>

#include "motion/bvh.hpp"

namespace t2imu {

struct AsfSkeleton {
    BvhMotion structure;     // joints, parents and offsets (ASF units); no channels or frames
    double metres_per_unit;  // 0.0254 / length
    std::vector<Quat> axis;  // C of each joint (identity for End Sites)
    // Degrees of freedom of each joint in the order AMC lists their values: 0..2 = rx, ry, rz; 3..5 = tx, ty, tz.
    std::vector<std::vector<int>> dofs;
};

AsfSkeleton parse_asf(const std::string& text, const std::string& source);
AsfSkeleton read_asf(const std::string& path);

// The local pose of every frame of an AMC file on `skeleton`.
std::vector<BvhPose> parse_amc(const std::string& text, const AsfSkeleton& skeleton, const std::string& source);
std::vector<BvhPose> read_amc(const std::string& path, const AsfSkeleton& skeleton);

}  // namespace t2imu
