#include "motion/jump_series.hpp"

#include <string>

#include "core/error.hpp"
#include "motion/motion_edit.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

using namespace smpl22;

void validate(const JumpSeriesOptions& o) {
    check_option_range(o.blend_s, 0.05, 0.3, "jump series options", "blend_s");
}

JointSequence chain_jumps(const std::vector<JointSequence>& jumps, const JumpSeriesOptions& o) {
    validate(o);
    if (jumps.size() < 2) throw Error("chain_jumps", "jumps", "at least two jumps");
    const double fps = jumps[0].fps;
    const int blend = std::max(1, frames_of(o.blend_s, fps));
    for (const JointSequence& j : jumps) {
        if (j.num_joints != kNumJoints || j.fps != fps)
            throw Error("chain_jumps", "jumps", "SMPL-22 joints at one frame rate");
        if (j.num_frames < 3 * blend) throw Error("chain_jumps", "jumps", "jumps of at least three blend windows");
    }
    JointSequence out = jumps[0];
    for (size_t i = 1; i < jumps.size(); ++i) {
        const int start = out.num_frames - blend;  // the first frame the next jump overlaps
        // Turned about its first pelvis position to face the way the series does there, and moved to stand there.
        const JointSequence next =
            turned_to_face(jumps[i], 0, body_facing(out, start), jumps[i].at(0, pelvis), out.at(start, pelvis));
        for (int f = 0; f < blend; ++f) {
            const double w = (f + 1.0) / (blend + 1.0);
            for (int j = 0; j < kNumJoints; ++j)
                out.at(start + f, j) = (1 - w) * out.at(start + f, j) + w * next.at(f, j);
        }
        out.positions.insert(out.positions.end(), next.positions.begin() + blend * kNumJoints, next.positions.end());
        out.num_frames += next.num_frames - blend;
    }
    restore_bone_lengths(out, bone_lengths(jumps[0], 0));
    return out;
}

}  // namespace t2imu
