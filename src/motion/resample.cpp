#include "motion/resample.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace t2imu {

namespace {

// Files print their frame time rounded (0.00833333 for 1/120 s; Bandai Namco's 30 fps reads 30.00003), so times
// within a thousandth of a frame of a source frame are taken as that frame: the last frame is kept and exact
// decimations stay exact.
constexpr double kSnap = 1e-3;

double snapped(double s) { return std::fabs(s - std::round(s)) < kSnap ? std::round(s) : s; }

}  // namespace

std::vector<BvhPose> resample_poses(const std::vector<BvhPose>& src, double frame_time, double target_fps) {
    if (src.empty()) throw Error("resample", "frames", "at least one source frame", "0");
    if (!(target_fps > 0) || !(frame_time > 0)) throw Error("resample", "rate", "positive frame rates");
    const double span = static_cast<double>(src.size() - 1) * frame_time;
    const size_t frames = static_cast<size_t>(std::floor(span * target_fps + kSnap)) + 1;
    std::vector<BvhPose> out;
    out.reserve(frames);
    for (size_t k = 0; k < frames; ++k) {
        const double s = snapped(static_cast<double>(k) / target_fps / frame_time);  // position in source frames
        const size_t i = static_cast<size_t>(std::floor(s));
        if (i >= src.size() - 1) {
            out.push_back(src.back());
            continue;
        }
        const double a = std::max(0.0, s - static_cast<double>(i));
        out.push_back(a == 0 ? src[i] : interpolate_pose(src[i], src[i + 1], a));
    }
    return out;
}

void interpolate_frame(const JointSequence& m, double s, JointSequence& out, int frame) {
    s = std::clamp(s, 0.0, static_cast<double>(m.num_frames - 1));
    const int i = std::min(static_cast<int>(std::floor(s)), m.num_frames - 1);
    const double t = s - i;
    auto at = [&](int f, int j) { return m.at(std::clamp(f, 0, m.num_frames - 1), j); };
    for (int j = 0; j < m.num_joints; ++j) {
        const Eigen::Vector3d p0 = at(i - 1, j), p1 = at(i, j), p2 = at(i + 1, j), p3 = at(i + 2, j);
        out.at(frame, j) = 0.5 * ((2 * p1) + (p2 - p0) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t * t +
                                  (3 * p1 - p0 - 3 * p2 + p3) * t * t * t);
    }
}

JointSequence resample_joints(const JointSequence& m, double fps) {
    if (!(fps > 0) || m.num_frames < 1) throw Error("resample_joints", "fps", "a positive rate and at least one frame");
    const int n = static_cast<int>(std::floor((m.num_frames - 1) * fps / m.fps + kSnap)) + 1;
    JointSequence out(n, m.num_joints, fps);
    for (int k = 0; k < n; ++k) interpolate_frame(m, snapped(k * m.fps / fps), out, k);
    return out;
}

}  // namespace t2imu
