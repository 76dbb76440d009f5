#include "motion/jump_series.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "motion/motion_edit.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

using Eigen::Vector3d;
using namespace smpl22;

namespace {

// `next` turned about the vertical through its first pelvis position and moved so that frame 0 stands at `at`
// (horizontally) facing `facing`; heights unchanged.
JointSequence placed(const JointSequence& next, const Vector3d& at, const Vector3d& facing) {
    const Vector3d from = body_facing(next, 0);
    const double turn = std::atan2(facing.z(), facing.x()) - std::atan2(from.z(), from.x());  // in the x-z plane, x towards z
    const double c = std::cos(turn), s = std::sin(turn);
    const Vector3d pivot = next.at(0, pelvis);
    JointSequence m = next;
    for (Vector3d& p : m.positions) {
        const double x = p.x() - pivot.x(), z = p.z() - pivot.z();
        p.x() = at.x() + c * x - s * z;
        p.z() = at.z() + s * x + c * z;
    }
    return m;
}

}  // namespace

void validate(const JumpSeriesOptions& o) { check_option_range(o.blend_s, 0.05, 0.3, "jump series options", "blend_s"); }

JointSequence chain_jumps(const std::vector<JointSequence>& jumps, const JumpSeriesOptions& o) {
    validate(o);
    if (jumps.size() < 2) throw Error("chain_jumps", "jumps", "at least two jumps");
    const double fps = jumps[0].fps;
    const int blend = std::max(1, frames_of(o.blend_s, fps));
    for (const JointSequence& j : jumps) {
        if (j.num_joints != kNumJoints || j.fps != fps) throw Error("chain_jumps", "jumps", "SMPL-22 joints at one frame rate");
        if (j.num_frames < 3 * blend) throw Error("chain_jumps", "jumps", "jumps of at least three blend windows");
    }
    JointSequence out = jumps[0];
    for (size_t i = 1; i < jumps.size(); ++i) {
        const int start = out.num_frames - blend;  // the first frame the next jump overlaps
        const JointSequence next = placed(jumps[i], out.at(start, pelvis), body_facing(out, start));
        for (int f = 0; f < blend; ++f) {
            const double w = (f + 1.0) / (blend + 1.0);
            for (int j = 0; j < kNumJoints; ++j) out.at(start + f, j) = (1 - w) * out.at(start + f, j) + w * next.at(f, j);
        }
        out.positions.insert(out.positions.end(), next.positions.begin() + blend * kNumJoints, next.positions.end());
        out.num_frames += next.num_frames - blend;
    }
    restore_bone_lengths(out, bone_lengths(jumps[0], 0));
    return out;
}

}  // namespace t2imu
