// How the joints of a motion-capture skeleton become the 22 SMPL joints of HumanML3D. One map per skeleton
// flavour found in open motion capture; each SMPL joint centre is a source joint, or a point on the segment
// between two source joints where the source has no joint at that place (e.g. SMPL's three spine joints on a
// two-joint source spine). The flavour is recognised by its joint names.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "motion/bvh.hpp"

namespace t2imu {

struct JointSource {
    std::string from;  // source joint name ("<joint>/end" for an End Site)
    std::string to;    // "" when the SMPL joint is `from` itself
    double t = 0;      // position = (1 - t) * from + t * to
};

struct SkeletonMap {
    std::string flavour;     // "cgspeed_daz", "iclone_cc_base", "bandai_namco", "hdm05_asf_amc", "reactidle_rigify"
    double metres_per_unit;  // the flavour's length unit
    PositionChannels positions = PositionChannels::replace_offset;  // see bvh.hpp
    // The converter prepended a T-pose frame: the first frame has a root rotation of exactly (0, 0, 0)
    // (cgspeed's CMU conversions; two of the 20 fps files still carry such a frame, with the root far below the
    // floor).
    bool zero_root_first_frame_is_tpose = false;
    std::array<JointSource, 22> joints;  // in smpl22 joint order
};

const std::vector<SkeletonMap>& skeleton_maps();
// The map whose joints all exist in `joint_names`. Otherwise throws an Error naming the SMPL joints that the
// closest flavour could not map.
const SkeletonMap& find_skeleton_map(const std::vector<std::string>& joint_names, const std::string& source);

}  // namespace t2imu
