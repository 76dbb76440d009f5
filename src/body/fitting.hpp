// Joints -> a posed body (the paper's joints2smpl step, done analytically).
//
// Every segment's orientation is read off the input joints (segments.hpp: long axis from the bone, twist from
// a neighbouring bone), then the body's own skeleton is posed with those orientations by forward kinematics:
// joint j = joint parent(j) + R_parent(j) (rest_j - rest_parent(j)). The motion is retargeted to the body's
// proportions: bone directions are kept, bone lengths are the body's, and the root trajectory (all three axes,
// so the feet stay on the floor) is scaled by the ratio of the body's leg length (hip-knee-ankle) to the
// input's. Nothing is iterated, so a frame costs a few microseconds.
//
// Fit error: per joint, the distance between the posed body's joint and the input joint scaled by the same
// leg ratio (mm): zero when the body has the input's proportions, otherwise the proportion mismatch.
#pragma once
#include <array>
#include <vector>

#include "body/body_model.hpp"
#include "motion/joint_sequence.hpp"

namespace t2imu {

struct FitOptions {
    bool keep_input_joints = false;  // pose the input skeleton as it is (--body none)
};

struct FittedMotion {
    double fps = 20;
    double leg_scale = 1;  // body leg length / input leg length
    std::vector<PosedFrame> frames;
    std::array<double, smpl22::kNumJoints> mean_error_mm{}, max_error_mm{};
};

std::vector<Joints22> joints22_frames(const JointSequence& motion);  // refuses a joint count other than 22
double leg_length(const Joints22& x);                                // mean of the two hip-knee-ankle chains, m

FittedMotion fit_body(const JointSequence& motion, const BodyModel& body, const FitOptions& options = {});

// Forward kinematics of a skeleton: rest joints, segment orientations and the root position.
Joints22 pose_skeleton(const Joints22& rest, const Rotations22& rotation, const Eigen::Vector3d& root);

}  // namespace t2imu
