#include "motion/gait_splice.hpp"

#include <cmath>
#include <optional>

#include "core/error.hpp"
#include "motion/foot_contacts.hpp"
#include "motion/motion_edit.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

using Eigen::Vector3d;
using namespace smpl22;

namespace {

int ankle_of(Foot foot) { return foot == Foot::left ? left_ankle : right_ankle; }

// The middle frame of a planted phase of `foot` that holds `half` frames on each side of it, searched from the
// end (last = true) or from the start; none if there is no such phase.
std::optional<int> mid_stance(const JointSequence& m, Foot foot, int half, bool last) {
    const std::vector<StancePhase> phases = detect_planted_phases(m);
    std::optional<int> found;
    for (const StancePhase& p : phases) {
        // A phase cut by the clip's start or end has no known middle: its mid-stance would not match the other's.
        if (p.foot != foot || p.first_frame == 0 || p.last_frame == m.num_frames - 1) continue;
        const int mid = (p.first_frame + p.last_frame) / 2;
        if (mid - half < p.first_frame || mid + half > p.last_frame) continue;
        if (mid - half < 0 || mid + half >= m.num_frames) continue;
        found = mid;
        if (!last) break;
    }
    return found;
}

// `m` turned about the vertical so that it faces `facing` at `frame`, then moved so that `joint` at `frame` lies
// at `at`.
JointSequence placed_at(const JointSequence& m, int frame, int joint, const Vector3d& at, const Vector3d& facing) {
    const Vector3d from = body_facing(m, frame);
    const double turn = std::atan2(facing.z(), facing.x()) - std::atan2(from.z(), from.x());  // x towards z
    const double c = std::cos(turn), s = std::sin(turn);
    JointSequence out = m;
    for (Vector3d& p : out.positions) p = Vector3d(c * p.x() - s * p.z(), p.y(), s * p.x() + c * p.z());
    const Vector3d shift = at - out.at(frame, joint);
    for (Vector3d& p : out.positions) p += shift;
    return out;
}

}  // namespace

void validate(const GaitSpliceOptions& o) { check_option_range(o.blend_s, 0.05, 0.4, "gait splice options", "blend_s"); }

GaitSplice splice_at_stance(const JointSequence& first, const JointSequence& second, const GaitSpliceOptions& o) {
    validate(o);
    for (const JointSequence* m : {&first, &second})
        if (m->num_joints != kNumJoints || m->fps != first.fps || m->num_frames < 3)
            throw Error("splice_at_stance", "motions", "SMPL-22 joints at one frame rate");
    const int half = std::max(1, frames_of(o.blend_s / 2, first.fps));
    std::optional<int> a, b;
    Foot foot = Foot::left;
    for (Foot f : {Foot::left, Foot::right}) {  // the foot whose last stance in `first` comes later: less is cut
        const std::optional<int> fa = mid_stance(first, f, half, true), fb = mid_stance(second, f, half, false);
        if (!fa || !fb) continue;
        if (!a || *fa > *a) { a = fa; b = fb; foot = f; }
    }
    if (!a) throw Error("splice_at_stance", "motions", "a planted phase of one foot at the end of the first and the start of the second");
    const int ankle = ankle_of(foot);
    const JointSequence next = placed_at(second, *b, ankle, first.at(*a, ankle), body_facing(first, *a));

    GaitSplice out;
    out.motion = slice_frames(first, 0, *a - half);
    const int blend = 2 * half + 1;
    for (int k = 0; k < blend; ++k) {
        const double w = (k + 1.0) / (blend + 1.0);
        for (int j = 0; j < kNumJoints; ++j)
            out.motion.positions.push_back((1 - w) * first.at(*a - half + k, j) + w * next.at(*b - half + k, j));
    }
    out.motion.positions.insert(out.motion.positions.end(), next.positions.begin() + (*b + half + 1) * kNumJoints, next.positions.end());
    out.motion.num_frames = static_cast<int>(out.motion.positions.size()) / kNumJoints;
    out.splice_frame = *a;
    restore_bone_lengths(out.motion, bone_lengths(first, 0));
    return out;
}

}  // namespace t2imu
