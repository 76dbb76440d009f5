#include "motion/foot_contacts.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

namespace {

// Velocity of joint j at frame f (m/s): central difference, one-sided at the ends.
Eigen::Vector3d velocity(const JointSequence& m, int f, int j) {
    const int a = std::max(0, f - 1), b = std::min(m.num_frames - 1, f + 1);
    return (m.at(b, j) - m.at(a, j)) * m.fps / (b - a);
}

double horizontal_speed(const JointSequence& m, int f, int j) {
    const Eigen::Vector3d v = velocity(m, f, j);
    return std::hypot(v.x(), v.z());
}

bool still(const JointSequence& m, int f, int j) {
    const Eigen::Vector3d v = velocity(m, f, j);
    return std::hypot(v.x(), v.z()) < kStanceSpeed && std::abs(v.y()) < kPlantVerticalSpeed;
}

bool low_and_slow(const JointSequence& m, int f, int j, double lowest) {
    return m.at(f, j).y() <= lowest + kStanceHeight && horizontal_speed(m, f, j) < kStanceSpeed;
}

double lowest_height(const JointSequence& m, int j) {
    double low = m.at(0, j).y();
    for (int f = 1; f < m.num_frames; ++f) low = std::min(low, m.at(f, j).y());
    return low;
}

// Sets every run of at most `gap` false flags that has a true flag on both sides.
void close_short_gaps(std::vector<bool>& stance, int gap) {
    const int n = static_cast<int>(stance.size());
    for (int f = 1; f < n;) {
        if (stance[static_cast<size_t>(f)] || !stance[static_cast<size_t>(f - 1)]) {
            ++f;
            continue;
        }
        int end = f;
        while (end < n && !stance[static_cast<size_t>(end)]) ++end;
        if (end < n && end - f <= gap) std::fill(stance.begin() + f, stance.begin() + end, true);
        f = end;
    }
}

void require_walk(const JointSequence& m) {
    if (m.num_joints != smpl22::kNumJoints)
        throw Error("foot contacts", "joints", "22 SMPL joints", std::to_string(m.num_joints));
    if (m.num_frames < 3) throw Error("foot contacts", "frames", "at least 3", std::to_string(m.num_frames));
}

}  // namespace

std::vector<bool> stance_frames(const JointSequence& m, Foot foot) {
    require_walk(m);
    const std::array<int, 2>& joints = foot == Foot::left ? smpl22::kFootLeft : smpl22::kFootRight;
    const double low_ankle = lowest_height(m, joints[0]), low_toe = lowest_height(m, joints[1]);
    std::vector<bool> stance(static_cast<size_t>(m.num_frames));
    for (int f = 0; f < m.num_frames; ++f)
        stance[static_cast<size_t>(f)] =
            low_and_slow(m, f, joints[0], low_ankle) || low_and_slow(m, f, joints[1], low_toe);
    close_short_gaps(stance, std::max(1, frames_of(kMaxStanceGapSeconds, m.fps)));
    return stance;
}

std::vector<bool> planted_frames(const JointSequence& m, Foot foot) {
    require_walk(m);
    const std::array<int, 2>& joints = foot == Foot::left ? smpl22::kFootLeft : smpl22::kFootRight;
    std::vector<bool> planted(static_cast<size_t>(m.num_frames));
    for (int f = 0; f < m.num_frames; ++f)
        planted[static_cast<size_t>(f)] = still(m, f, joints[0]) || still(m, f, joints[1]);
    close_short_gaps(planted, std::max(1, frames_of(kMaxStanceGapSeconds, m.fps)));
    return planted;
}

namespace {

// Runs of true flags at least min_frames long, as phases of `foot`.
std::vector<StancePhase> runs_of(const std::vector<bool>& flags, Foot foot, int min_frames) {
    std::vector<StancePhase> phases;
    const int n = static_cast<int>(flags.size());
    for (int f = 0; f < n;) {
        if (!flags[static_cast<size_t>(f)]) {
            ++f;
            continue;
        }
        int last = f;
        while (last + 1 < n && flags[static_cast<size_t>(last + 1)]) ++last;
        if (last - f + 1 >= min_frames) phases.push_back({foot, f, last});
        f = last + 1;
    }
    return phases;
}

std::vector<StancePhase> phases_of_both_feet(const JointSequence& m,
                                             std::vector<bool> (*flags)(const JointSequence&, Foot)) {
    std::vector<StancePhase> phases;
    const int min_frames = frames_of(kMinStanceSeconds, m.fps);
    for (Foot foot : {Foot::left, Foot::right}) {
        const std::vector<StancePhase> runs = runs_of(flags(m, foot), foot, min_frames);
        phases.insert(phases.end(), runs.begin(), runs.end());
    }
    std::stable_sort(phases.begin(), phases.end(),
                     [](const StancePhase& a, const StancePhase& b) { return a.first_frame < b.first_frame; });
    return phases;
}

}  // namespace

std::vector<StancePhase> detect_stance_phases(const JointSequence& m) { return phases_of_both_feet(m, stance_frames); }

std::vector<StancePhase> detect_planted_phases(const JointSequence& m) {
    return phases_of_both_feet(m, planted_frames);
}

}  // namespace t2imu
