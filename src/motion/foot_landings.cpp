#include "motion/foot_landings.hpp"

#include <algorithm>

#include "motion/skeleton.hpp"

namespace t2imu {

namespace {

constexpr int kMinSlowFrames = 2;

// Central-difference speed of `joint` at frame f (one-sided at the ends), m/s.
double joint_speed(const JointSequence& m, int joint, int f) {
    const int a = std::max(0, f - 1), b = std::min(m.num_frames - 1, f + 1);
    if (a == b) return 0;
    return (m.at(b, joint) - m.at(a, joint)).norm() * m.fps / (b - a);
}

void landings_of(const JointSequence& m, int ankle, std::vector<Landing>* out) {
    std::vector<bool> slow(static_cast<size_t>(m.num_frames));
    for (int f = 0; f < m.num_frames; ++f) slow[static_cast<size_t>(f)] = joint_speed(m, ankle, f) < kLandingSpeed;
    for (int f = 1; f + kMinSlowFrames <= m.num_frames; ++f) {
        if (slow[static_cast<size_t>(f - 1)]) continue;
        bool run = true;
        for (int k = 0; k < kMinSlowFrames; ++k) run = run && slow[static_cast<size_t>(f + k)];
        if (!run) continue;
        out->push_back({(f - 0.5) / m.fps});
    }
}

}  // namespace

std::vector<Landing> detect_landings(const JointSequence& motion) {
    std::vector<Landing> out;
    if (motion.num_frames < 3) return out;
    landings_of(motion, smpl22::left_ankle, &out);
    landings_of(motion, smpl22::right_ankle, &out);
    std::sort(out.begin(), out.end(), [](const Landing& a, const Landing& b) { return a.time_s < b.time_s; });
    return out;
}

}  // namespace t2imu
