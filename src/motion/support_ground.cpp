#include "motion/support_ground.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "motion/skeleton.hpp"

namespace t2imu {

namespace {

Foothold foothold_of(const JointSequence& m, const StancePhase& phase) {
    const std::array<int, 2>& joints = phase.foot == Foot::left ? smpl22::kFootLeft : smpl22::kFootRight;
    Foothold h{phase,
               std::numeric_limits<double>::infinity(),
               Eigen::Vector2d::Zero(),
               Eigen::Vector2d::Zero(),
               m.num_frames,
               false,
               false};
    for (int f = phase.first_frame; f <= phase.last_frame; ++f) {
        const Eigen::Vector3d& ankle = m.at(f, joints[0]);
        const Eigen::Vector3d& toe = m.at(f, joints[1]);
        h.ankle += Eigen::Vector2d(ankle.x(), ankle.z());
        h.toe += Eigen::Vector2d(toe.x(), toe.z());
        h.height = std::min({h.height, ankle.y(), toe.y()});
    }
    const double n = phase.last_frame - phase.first_frame + 1;
    h.ankle /= n;
    h.toe /= n;
    return h;
}

bool on_floor(const Foothold& h) { return std::abs(h.height) <= kFloorBand; }

// Whether the body stands on h: at some frame of it the foot is the body's lowest part (within kFloorBand).
bool carries_body(const JointSequence& m, const Foothold& h) {
    const std::array<int, 2>& foot = h.phase.foot == Foot::left ? smpl22::kFootLeft : smpl22::kFootRight;
    for (int f = h.phase.first_frame; f <= h.phase.last_frame; ++f)
        if (std::min(m.at(f, foot[0]).y(), m.at(f, foot[1]).y()) <= lowest_joint_height_at(m, f) + kFloorBand)
            return true;
    return false;
}

double horizontal_distance(const Foothold& a, const Foothold& b) {
    return ((a.ankle + a.toe) - (b.ankle + b.toe)).norm() / 2;
}

// Whether a person standing on `from` can step onto `to`.
bool a_step(const Foothold& from, const Foothold& to) {
    const double rise = std::abs(to.height - from.height);
    return rise <= kFloorBand || (rise <= kMaxFootholdRise && horizontal_distance(from, to) >= kMinStepDistance);
}

// One pass of the chain rule in the order [begin, end) walks: a foothold on the floor, or one that can be
// stood on and is a step from the last grounded one met in this pass, is grounded.
template <typename It>
void ground_along(It begin, It end) {
    It last = end;
    for (It it = begin; it != end; ++it) {
        if (!it->grounded) it->grounded = on_floor(*it) || (it->raised && last != end && a_step(*last, *it));
        if (it->grounded) last = it;
    }
}

// The lowest raised foothold, when none is on the floor, the clip touches the floor and it is one step above it.
void link_lowest_to_floor(const JointSequence& m, std::vector<Foothold>& holds) {
    if (std::any_of(holds.begin(), holds.end(), on_floor)) return;
    auto low = std::min_element(holds.begin(), holds.end(), [](const Foothold& a, const Foothold& b) {
        return (a.raised ? a.height : INFINITY) < (b.raised ? b.height : INFINITY);
    });
    if (low == holds.end() || !low->raised || low->height > kMaxFootholdRise) return;
    low->grounded = std::abs(lowest_joint_height(m)) <= kFloorBand;
}

// Horizontal distance (m) from p to the footprint's ankle-toe segment.
double footprint_distance(const Foothold& h, const Eigen::Vector3d& p) {
    const Eigen::Vector2d q(p.x(), p.z()), d = h.toe - h.ankle;
    const double length2 = d.squaredNorm();
    const double u = length2 > 0 ? std::clamp((q - h.ankle).dot(d) / length2, 0.0, 1.0) : 0.0;
    return (q - h.ankle - u * d).norm();
}

}  // namespace

std::vector<Foothold> infer_footholds(const JointSequence& m) {
    std::vector<Foothold> holds;
    for (const StancePhase& p : detect_planted_phases(m)) holds.push_back(foothold_of(m, p));
    const int min_frames = frames_of(kMinRaisedStanceSeconds, m.fps);
    for (Foothold& h : holds) {
        h.raised =
            h.height > kFloorBand && h.phase.last_frame - h.phase.first_frame + 1 >= min_frames && carries_body(m, h);
        for (const Foothold& next : holds)
            if (next.phase.foot == h.phase.foot && next.phase.first_frame > h.phase.first_frame) {
                h.until_frame = next.phase.first_frame;
                break;
            }
    }
    link_lowest_to_floor(m, holds);
    ground_along(holds.begin(), holds.end());    // a climb from the floor
    ground_along(holds.rbegin(), holds.rend());  // a descent to the floor
    return holds;
}

SupportGround::SupportGround(const JointSequence& m) {
    for (const Foothold& h : infer_footholds(m))
        if (h.raised && h.grounded) footholds_.push_back(h);
}

double SupportGround::height_at(const Eigen::Vector3d& p, int frame) const {
    double best = kFootprintReach, height = 0.0;
    for (const Foothold& h : footholds_) {
        if (frame < h.phase.first_frame || frame >= h.until_frame) continue;
        const double d = footprint_distance(h, p);
        if (d <= best) best = d, height = h.height;
    }
    return height;
}

}  // namespace t2imu
