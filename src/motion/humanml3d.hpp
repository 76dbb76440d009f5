// The HumanML3D motion representation (Guo et al. 2022), reproducing the official motion_representation
// code of EricGuo5513/HumanML3D, quirks included, so that features made here equal the released dataset's.
//
// Layout of one 263-dim feature row (frame t of F-1; 22 joints, Y up, metres, 20 fps):
//   [0]        root rotation velocity about Y: arcsin of the y component of q_root[t+1] q_root[t]^-1, i.e. the
//              half-angle in radians per frame
//   [1:3]      root linear velocity in the XZ plane, in the root's facing frame (metres per frame)
//   [3]        root height (metres)
//   [4:67]     rotation-invariant joint positions ("ric"): joints 1..21 relative to the root's XZ, rotated into
//              the root's facing frame (21 x 3)
//   [67:193]   local joint rotations of joints 1..21 in the continuous 6D representation (21 x 6)
//   [193:259]  joint velocities of all 22 joints in the root's facing frame (metres per frame, 22 x 3)
//   [259:261]  left foot contacts (ankle, foot), [261:263] right foot contacts: 1 when the joint moved less than
//              sqrt(0.002) m since the previous frame
//
// Official quirk kept on purpose: the initial facing uses across = (j2 - j1) + (j17 - j16), while the IK's root
// rotation uses (j1 - j2) + (j17 - j16) (face_joint_indx unpacked in two different orders); and the IK sets the
// first frame's root rotation to the identity.
#pragma once
#include <array>
#include <vector>

#include "motion/joint_sequence.hpp"
#include "motion/quaternion.hpp"

namespace t2imu {

constexpr int kFeatureDim = 263;
using PoseQuats = std::array<Quat, 22>;  // one frame's quaternions: [0] root (world), others local to parent

struct ProcessFileResult {
    FeatureMatrix features;                  // [F-1, 263]
    JointSequence after_uniform_skeleton;    // retargeted to smpl22::kTargetOffsets, before floor/origin/facing
    JointSequence global_positions;          // on the floor, root XZ at the origin at frame 0, facing +Z
    JointSequence local_positions;           // get_rifke: root-relative XZ, each frame rotated to face +Z
    Eigen::Vector3d forward_init;            // initial facing (unit, XZ plane)
    Quat root_quat_init;                     // rotation taking forward_init to +Z
    Eigen::MatrixXd l_velocity;              // [F-1, 2] root XZ velocity in the facing frame
    std::vector<PoseQuats> ik_quats_smooth;  // IK with the Gaussian-smoothed forward direction
};

ProcessFileResult process_file(const JointSequence& joints, double feet_threshold = 0.002);
FeatureMatrix joints_to_features(const JointSequence& joints);  // process_file(...).features

// The same motion at another frame rate (the capture rate, t2imu data build's capture_joints/) placed where
// process_file places `reference`, that motion at 20 fps from the same first instant: retargeted to
// smpl22::kTargetOffsets, lowered by the reference's floor, moved by its frame-0 root XZ and turned by its frame-0
// facing. At the reference's frame times it equals process_file(reference).global_positions up to float32
// rounding (and the lowest point between 20 fps frames may dip under the floor by millimetres).
JointSequence place_like_process_file(const JointSequence& joints, const JointSequence& reference);

// Naive inverse kinematics (Skeleton.inverse_kinematics_np): the root rotation turns the body's forward
// direction to +Z; each bone's local rotation is the shortest arc from its rest direction (smpl22::kRawOffsets)
// to its current direction, relative to the chain's accumulated rotation. Bone twist is not observable from
// positions and is left at zero. smooth_forward: smooth the forward direction over time (sigma 20 frames).
std::vector<PoseQuats> inverse_kinematics(const JointSequence& joints, bool smooth_forward);
// Forward kinematics over the HumanML3D chains with bone vectors `offsets` (metres, rest pose).
JointSequence forward_kinematics(const std::vector<PoseQuats>& quats, const std::vector<Eigen::Vector3d>& root_pos,
                                 const std::array<Eigen::Vector3d, 22>& offsets);
// Bone vectors of the rest pose implied by one frame of joints: raw offset direction x bone length.
std::array<Eigen::Vector3d, 22> offsets_from_joints(const JointSequence& joints, int frame);
// Retargets a motion to the bone lengths `target_offsets`, scaling the root trajectory by the leg-length ratio.
JointSequence uniform_skeleton(const JointSequence& joints, const std::array<Eigen::Vector3d, 22>& target_offsets);

// Root rotation (about Y) and position (metres) of every frame, integrated from the velocity channels.
struct RootTrajectory {
    std::vector<Quat> rotation;
    std::vector<Eigen::Vector3d> position;
};
RootTrajectory recover_root_rot_pos(const FeatureMatrix& features);
// [F, 263] features -> [F, 22, 3] joint positions from the rotation-invariant positions (what becomes
// HumanML3D's new_joints).
JointSequence recover_from_ric(const FeatureMatrix& features);
// [F, 263] -> joints by forward kinematics of the 6D rotations on bone vectors `offsets`.
JointSequence recover_from_rot(const FeatureMatrix& features, const std::array<Eigen::Vector3d, 22>& offsets);

}  // namespace t2imu
