#include "motion/walk_turn.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "motion/foot_contacts.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

namespace {

using Eigen::Vector3d;

// A rigid motion of the horizontal plane: p -> R(angle) p + t, R turning +Z towards +X (left) for angle > 0.
struct PlaneMotion {
    double angle = 0, tx = 0, tz = 0;
    Vector3d apply(const Vector3d& p) const {
        const double c = std::cos(angle), s = std::sin(angle);
        return {c * p.x() + s * p.z() + tx, p.y(), -s * p.x() + c * p.z() + tz};
    }
    // This followed by a turn of `d` about the vertical through `pivot`.
    PlaneMotion then_turn(double d, const Vector3d& pivot) const {
        PlaneMotion r{angle + d, 0, 0};
        const Vector3d t = PlaneMotion{d, 0, 0}.apply(Vector3d(tx - pivot.x(), 0, tz - pivot.z()));
        r.tx = t.x() + pivot.x(), r.tz = t.z() + pivot.z();
        return r;
    }
};

double minimum_jerk(double u) {
    u = std::clamp(u, 0.0, 1.0);
    return u * u * u * (10 - 15 * u + 6 * u * u);
}

Vector3d foot_point(const JointSequence& m, int f, Foot foot) {
    const auto& j = foot == Foot::left ? smpl22::kFootLeft : smpl22::kFootRight;
    return (m.at(f, j[0]) + m.at(f, j[1])) / 2;
}

}  // namespace

JointSequence turn_walk(const JointSequence& walk, const WalkTurnOptions& o) {
    if (walk.num_joints != smpl22::kNumJoints || walk.num_frames < 3)
        throw Error("walk turn", "joints", "22 joints and at least 3 frames");
    const double length = (walk.num_frames - 1) / walk.fps;
    if (!(std::abs(o.turn_rad) <= M_PI)) throw Error("walk turn", "turn_rad", "-pi to pi", std::to_string(o.turn_rad));
    if (!(o.duration_s > 0 && o.start_s >= 0 && o.start_s + o.duration_s <= length))
        throw Error("walk turn", "start_s, duration_s", "a turn within the walk's " + std::to_string(length) + " s",
                    std::to_string(o.start_s) + " + " + std::to_string(o.duration_s));
    const std::vector<bool> left = planted_frames(walk, Foot::left), right = planted_frames(walk, Foot::right);
    const auto heading = [&](int f) { return o.turn_rad * minimum_jerk((f / walk.fps - o.start_s) / o.duration_s); };
    JointSequence out = walk;
    PlaneMotion t;
    std::array<int, 2> landed{0, 0};  // per foot, the first frame of its current planted run
    for (int f = 0; f < walk.num_frames; ++f) {
        const size_t i = static_cast<size_t>(f);
        if (f > 0 && left[i] && !left[i - 1]) landed[0] = f;
        if (f > 0 && right[i] && !right[i - 1]) landed[1] = f;
        if (f > 0) {
            // In double support the foot that landed last carries the turn; the other is about to push off.
            Vector3d pivot = walk.at(f, smpl22::pelvis);
            if (left[i] && (!right[i] || landed[0] >= landed[1]))
                pivot = foot_point(walk, f, Foot::left);
            else if (right[i])
                pivot = foot_point(walk, f, Foot::right);
            t = t.then_turn(heading(f) - heading(f - 1), t.apply(pivot));
        }
        for (int k = 0; k < walk.num_joints; ++k) out.at(f, k) = t.apply(walk.at(f, k));
    }
    return out;
}

}  // namespace t2imu
