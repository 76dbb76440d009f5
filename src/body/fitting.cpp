#include "body/fitting.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace t2imu {

using namespace smpl22;
using Eigen::Vector3d;

std::vector<Joints22> joints22_frames(const JointSequence& motion) {
    if (motion.num_joints != kNumJoints)
        throw Error("joints", "shape", "22 joints (SMPL-22)", std::to_string(motion.num_joints));
    std::vector<Joints22> frames(static_cast<size_t>(motion.num_frames));
    for (int f = 0; f < motion.num_frames; ++f)
        for (int j = 0; j < kNumJoints; ++j) frames[static_cast<size_t>(f)][static_cast<size_t>(j)] = motion.at(f, j);
    return frames;
}

double leg_length(const Joints22& x) {
    const double left = (x[left_hip] - x[left_knee]).norm() + (x[left_knee] - x[left_ankle]).norm();
    const double right = (x[right_hip] - x[right_knee]).norm() + (x[right_knee] - x[right_ankle]).norm();
    return (left + right) / 2;
}

Joints22 pose_skeleton(const Joints22& rest, const Rotations22& rotation, const Vector3d& root) {
    Joints22 x;
    x[0] = root;
    for (int j = 1; j < kNumJoints; ++j) {
        const size_t p = static_cast<size_t>(kParents[static_cast<size_t>(j)]);
        x[static_cast<size_t>(j)] = x[p] + rotation[p] * (rest[static_cast<size_t>(j)] - rest[p]);
    }
    return x;
}

FittedMotion fit_body(const JointSequence& motion, const BodyModel& body, const FitOptions& options) {
    const std::vector<Joints22> input = joints22_frames(motion);
    if (input.empty()) throw Error("joints", "frames", "at least one frame", "0");
    FittedMotion out;
    out.fps = motion.fps;
    const std::vector<Rotations22> rotations = segment_rotations(input, rest_axes(body.rest_joints()));
    double input_leg = 0;
    for (const Joints22& x : input) input_leg += leg_length(x);
    input_leg /= static_cast<double>(input.size());
    if (!(input_leg > 0)) throw Error("joints", "legs", "non-zero leg length", "0");
    out.leg_scale = options.keep_input_joints ? 1.0 : leg_length(body.rest_joints()) / input_leg;
    out.frames.resize(input.size());
    for (size_t f = 0; f < input.size(); ++f) {
        PosedFrame& frame = out.frames[f];
        frame.rotation = rotations[f];
        frame.joints = options.keep_input_joints
                           ? input[f]
                           : pose_skeleton(body.rest_joints(), rotations[f], out.leg_scale * input[f][0]);
        for (size_t j = 0; j < static_cast<size_t>(kNumJoints); ++j) {
            const double e = (frame.joints[j] - out.leg_scale * input[f][j]).norm() * 1000.0;
            out.mean_error_mm[j] += e / static_cast<double>(input.size());
            out.max_error_mm[j] = std::max(out.max_error_mm[j], e);
        }
    }
    return out;
}

}  // namespace t2imu
