// A motion as joint positions over time: [frames, joints, 3], metres, Y-up world frame, at `fps`.
#pragma once
#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "core/ndarray.hpp"

namespace t2imu {

struct JointSequence {
    int num_frames = 0;
    int num_joints = 22;
    double fps = 20.0;
    std::vector<Eigen::Vector3d> positions;  // frame-major: positions[f * num_joints + j]

    JointSequence() = default;
    JointSequence(int frames, int joints, double fps_);

    Eigen::Vector3d& at(int frame, int joint) { return positions[static_cast<size_t>(frame * num_joints + joint)]; }
    const Eigen::Vector3d& at(int frame, int joint) const {
        return positions[static_cast<size_t>(frame * num_joints + joint)];
    }
};

// The nearest whole number of frames to `seconds` at `fps`: how the motion edits turn their time constants
// (seconds) into frame counts at any rate.
inline int frames_of(double seconds, double fps) { return static_cast<int>(std::lround(seconds * fps)); }

// Throws Error naming `option` unless `fps` is a frame rate motion can have here: above 0, at most 1,000 fps
// (optical capture runs to ~480; a larger value is a typo, and frame counts derived from it would overflow).
void check_motion_fps(double fps, const std::string& option);

// The lowest joint's height (y, m) at `frame`, and over the whole motion (at least one frame and joint).
double lowest_joint_height_at(const JointSequence& s, int frame);
double lowest_joint_height(const JointSequence& s);

// Frames [begin, end) of `s`, same joints and rate.
JointSequence slice_frames(const JointSequence& s, int begin, int end);

// The frames of `a`, then those of `b` (same joint count and rate; Error otherwise).
JointSequence concatenate_frames(const JointSequence& a, const JointSequence& b);

// [F, J, 3] (any float or int dtype) -> JointSequence. Refuses a wrong rank or last dimension, fewer than
// `min_frames` frames, a joint count other than `joints` (when > 0), and NaN/inf, naming `source`.
JointSequence joint_sequence_from_array(const NdArray& a, const std::string& source, int joints = 22,
                                        int min_frames = 1, double fps = 20.0);
NdArray joint_sequence_to_array(const JointSequence& s);  // float32 [F, J, 3]

// Row-major [frames, channels] matrix for per-frame features (the 263-dim HumanML3D vectors).
using FeatureMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
FeatureMatrix feature_matrix_from_array(const NdArray& a, const std::string& source, int channels = 263);
NdArray feature_matrix_to_array(const FeatureMatrix& m);  // float32 [F, C]

}  // namespace t2imu
