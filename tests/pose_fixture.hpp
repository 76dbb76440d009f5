// A standing body whose geometry is known exactly, for the tests of motion attributes and descriptors.
#pragma once
#include <Eigen/Core>
#include <array>

namespace t2imu::test {

// HumanML3D's target skeleton (SMPL-22 joint order, metres, Y up) standing still, facing +Z with its left at +X:
// pelvis 0.9 m up, straight legs, ankles 0.05 m above the floor and toes on it, head 0.65 m above the pelvis.
std::array<Eigen::Vector3d, 22> standing_pose();

}  // namespace t2imu::test
