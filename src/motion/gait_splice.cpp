#include "motion/gait_splice.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "core/signal/gaussian_filter.hpp"
#include "motion/foot_contacts.hpp"
#include "motion/motion_edit.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

using Eigen::Vector3d;
using namespace smpl22;

namespace {

// The middle frame of a planted phase of `foot` among `phases` (of a motion of `frames` frames) that holds `half`
// frames on each side of it, the last such phase (last = true) or the first; none if there is no such phase.
std::optional<int> mid_stance(const std::vector<StancePhase>& phases, int frames, Foot foot, int half, bool last) {
    std::optional<int> found;
    for (const StancePhase& p : phases) {
        // A phase cut by the clip's start or end has no known middle: its mid-stance would not match the other's.
        if (p.foot != foot || p.first_frame == 0 || p.last_frame == frames - 1) continue;
        const int mid = (p.first_frame + p.last_frame) / 2;
        if (mid - half < p.first_frame || mid + half > p.last_frame) continue;
        found = mid;
        if (!last) break;
    }
    return found;
}

// The planted phases of `m`, found on its joints smoothed over time by a Gaussian of sd `smoothing_s` (0: as is).
std::vector<StancePhase> planted_phases(const JointSequence& m, double smoothing_s) {
    if (smoothing_s == 0) return detect_planted_phases(m);
    TimeSeries x(m.num_frames, 3 * m.num_joints);
    for (int f = 0; f < m.num_frames; ++f)
        for (int j = 0; j < m.num_joints; ++j) x.block<1, 3>(f, 3 * j) = m.at(f, j).transpose();
    const TimeSeries y = gaussian_filter1d_nearest(x, smoothing_s * m.fps);
    JointSequence smooth = m;
    for (int f = 0; f < m.num_frames; ++f)
        for (int j = 0; j < m.num_joints; ++j) smooth.at(f, j) = y.block<1, 3>(f, 3 * j).transpose();
    return detect_planted_phases(smooth);
}

}  // namespace

void validate(const GaitSpliceOptions& o) {
    check_option_range(o.blend_s, 0.05, 0.4, "gait splice options", "blend_s");
    check_option_range(o.contact_smoothing_s, 0.0, 0.1, "gait splice options", "contact_smoothing_s");
}

GaitSplice splice_at_stance(const JointSequence& first, const JointSequence& second, const GaitSpliceOptions& o) {
    validate(o);
    for (const JointSequence* m : {&first, &second})
        if (m->num_joints != kNumJoints || m->fps != first.fps || m->num_frames < 3)
            throw Error("splice_at_stance", "motions", "SMPL-22 joints at one frame rate");
    const int half = std::max(1, frames_of(o.blend_s / 2, first.fps));
    const std::vector<StancePhase> first_phases = planted_phases(first, o.contact_smoothing_s),
                                   second_phases = planted_phases(second, o.contact_smoothing_s);
    std::optional<int> a, b;
    Foot foot = Foot::left;
    for (Foot f : {Foot::left, Foot::right}) {  // the foot whose last stance in `first` comes later: less is cut
        const std::optional<int> fa = mid_stance(first_phases, first.num_frames, f, half, true),
                                 fb = mid_stance(second_phases, second.num_frames, f, half, false);
        if (!fa || !fb) continue;
        if (!a || *fa > *a) {
            a = fa;
            b = fb;
            foot = f;
        }
    }
    if (!a)
        throw Error("splice_at_stance", "motions",
                    "a planted phase of one foot at the end of the first and the start of the second");
    // `second` turned about its planted ankle and moved so that the ankle stands where it stands in `first`.
    const int ankle = kLegs[static_cast<size_t>(foot)].ankle;
    JointSequence next = turned_to_face(second, *b, body_facing(first, *a), second.at(*b, ankle), first.at(*a, ankle));
    const double rise = first.at(*a, ankle).y() - second.at(*b, ankle).y();
    for (Vector3d& p : next.positions) p.y() += rise;

    GaitSplice out;
    out.motion = slice_frames(first, 0, *a - half);
    const int blend = 2 * half + 1;
    for (int k = 0; k < blend; ++k) {
        const double w = (k + 1.0) / (blend + 1.0);
        for (int j = 0; j < kNumJoints; ++j)
            out.motion.positions.push_back((1 - w) * first.at(*a - half + k, j) + w * next.at(*b - half + k, j));
    }
    out.motion.positions.insert(out.motion.positions.end(), next.positions.begin() + (*b + half + 1) * kNumJoints,
                                next.positions.end());
    out.motion.num_frames = static_cast<int>(out.motion.positions.size()) / kNumJoints;
    out.splice_frame = *a;
    restore_bone_lengths(out.motion, bone_lengths(first, 0));
    return out;
}

GaitSplice splice_to_length(const JointSequence& first, const JointSequence& second, int frames,
                            const GaitSpliceOptions& o) {
    GaitSplice joined = splice_at_stance(first, second, o);
    const int n = joined.motion.num_frames;
    if (frames < 1 || n < frames)
        throw Error("splice_to_length", "frames", "1 to the join's " + std::to_string(n), std::to_string(frames));
    const int begin = std::clamp(joined.splice_frame - frames / 2, 0, n - frames);
    joined.motion = slice_frames(joined.motion, begin, begin + frames);
    joined.splice_frame -= begin;
    return joined;
}

}  // namespace t2imu
