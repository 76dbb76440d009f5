// Motion capture -> SMPL-22 joint positions (metres, Y up, HumanML3D's joint order) at a chosen frame rate.
#pragma once
#include <string>

#include "motion/joint_sequence.hpp"

namespace t2imu {

struct ImportOptions {
    double fps = 20.0;   // output frame rate; 0 = the capture rate (capture_fps_for)
    std::string format;  // "bvh", "amc" or "npy"; "" = from the file's extension
    std::string asf;  // the ASF skeleton of an AMC clip; "" = the .asf beside it whose name is a prefix of the clip's
    double source_fps = 120.0;  // AMC files do not record their rate; CMU and HDM05 capture at 120 fps
    char up = 'y';  // the source's up axis: 'y' (every built-in flavour) or 'z' (turned to Y up, right-handed)
};

// The rate a capture at `capture_fps` is kept at by ImportOptions::fps = 0: itself, or itself divided by the
// smallest whole number that brings it to at most kMaxCaptureFps (120 -> 60, 30 -> 30, 24 -> 24). Whole-number
// decimation picks captured frames and interpolates none: interpolating rotations between captured frames makes
// the joints' paths kinked at every captured frame, accelerations the capture never held. 60 fps keeps what a
// body moves at (under 30 Hz) and what virtual sensors at 50 Hz and HAR at 20 Hz can see.
constexpr double kMaxCaptureFps = 60.0;
double capture_fps_for(double capture_fps);

// BVH (any known skeleton flavour, see skeleton_map.hpp), ASF/AMC, or an .npy of [F,22,3] joints (taken as
// already at options.fps, which must then be given). A leading T-pose frame is dropped where the flavour has one
// (SkeletonMap). Throws Error for an unknown skeleton, a bad file or NaN.
JointSequence import_motion(const std::string& path, const ImportOptions& options = {});

}  // namespace t2imu
