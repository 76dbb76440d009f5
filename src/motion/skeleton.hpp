// The 22-joint SMPL skeleton of HumanML3D (paramUtil.py of EricGuo5513/HumanML3D): joint names and order,
// parents, the unit "raw offsets" that give each bone's rest direction, the kinematic chains, and the joints
// HumanML3D uses for facing and foot contact. World frame: Y up, metres; a canonicalised body faces +Z, so
// its left side is +X.
#pragma once
#include <Eigen/Core>
#include <array>
#include <string>

namespace t2imu::smpl22 {

constexpr int kNumJoints = 22;
constexpr double kFps = 20.0;  // HumanML3D's frame rate

enum Joint : int {
    pelvis = 0,
    left_hip,
    right_hip,
    spine1,
    left_knee,
    right_knee,
    spine2,
    left_ankle,
    right_ankle,
    spine3,
    left_foot,
    right_foot,
    neck,
    left_collar,
    right_collar,
    head,
    left_shoulder,
    right_shoulder,
    left_elbow,
    right_elbow,
    left_wrist,
    right_wrist
};

extern const std::array<const char*, kNumJoints> kJointNames;  // "pelvis", "left_hip", ...
extern const std::array<int, kNumJoints> kParents;             // -1 for the pelvis
// Unit rest directions of each joint's bone from its parent (t2m_raw_offsets); the pelvis has zero.
extern const std::array<Eigen::Vector3d, kNumJoints> kRawOffsets;
// The five chains (right leg, left leg, spine to head, right arm, left arm), as in t2m_kinematic_chain.
extern const std::array<std::array<int, 6>, 5> kKinematicChains;  // each padded with -1
extern const std::array<int, 5> kKinematicChainLengths;
// HumanML3D's target skeleton (sequence 000021, frame 0): bone vectors in metres in the rest pose, as the
// official Skeleton.get_offsets_joints computes them (float32 values). Every HumanML3D motion is retargeted
// to these bone lengths by process_file.
extern const std::array<Eigen::Vector3d, kNumJoints> kTargetOffsets;

// face_joint_indx = [2, 1, 17, 16]: right hip, left hip, right shoulder, left shoulder.
constexpr std::array<int, 4> kFaceJoints = {right_hip, left_hip, right_shoulder, left_shoulder};
constexpr std::array<int, 2> kFootLeft = {left_ankle, left_foot};     // fid_l
constexpr std::array<int, 2> kFootRight = {right_ankle, right_foot};  // fid_r
constexpr double kFootContactThreshold = 0.002;  // squared per-frame displacement, metres^2 (feet_thre)
// Mirror partner of each joint (left <-> right), for left-right mirroring.
extern const std::array<int, kNumJoints> kMirror;

}  // namespace t2imu::smpl22
