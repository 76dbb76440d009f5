// Resampling of a motion to another frame rate. Where the source skeleton's local transforms are at hand (an
// import), on them: joint rotations by slerp and translations linearly between the two nearest source frames,
// then forward kinematics. Where only joint positions are (an edited motion), by Catmull-Rom on the positions.
// Dropping frames alone would alias (and cannot reach rates that do not divide the source rate, e.g. 30 -> 20 fps).
#pragma once
#include <vector>

#include "motion/bvh.hpp"
#include "motion/joint_sequence.hpp"

namespace t2imu {

// Local poses at times k / target_fps for k = 0 .. while within the source's time span
// [0, (frames - 1) * frame_time]. source_poses[f] is the pose at time f * frame_time.
std::vector<BvhPose> resample_poses(const std::vector<BvhPose>& source_poses, double frame_time, double target_fps);

// Writes every joint of `m` at fractional frame `s` (clamped to [0, frames - 1]) into frame `frame` of `out`, by
// Catmull-Rom between m's frames: continuous velocity, so resampling adds no kink (and no acceleration spike)
// between frames, and exact at whole frames.
void interpolate_frame(const JointSequence& m, double s, JointSequence& out, int frame);

// `m` at times k / fps s, k = 0, 1, ... while within its span [0, (frames - 1) / m.fps] (interpolate_frame); a time
// within a thousandth of a frame of one of m's frames is taken as that frame, as resample_poses does.
JointSequence resample_joints(const JointSequence& m, double fps);

}  // namespace t2imu
