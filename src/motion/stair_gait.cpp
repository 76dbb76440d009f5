#include "motion/stair_gait.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/signal/gaussian_filter.hpp"
#include "motion/motion_edit.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

using Eigen::Vector3d;

namespace {

constexpr double kSideBySide = 0.15;  // m along the walk: footholds nearer than this share a tread
constexpr double kMinTravel = 1.5;    // m: at least two steps of a walk
constexpr double kPi = 3.14159265358979323846;

// A stance phase of the (retimed) walk and where it goes: moved `shift` m along the walk and raised `height` m.
struct Hold {
    StancePhase phase;
    double along = 0, shift = 0, height = 0;
    int tread = 0;
};

Vector3d foot_middle(const JointSequence& w, int f, Foot foot) {
    const LegJoints& leg = kLegs[static_cast<size_t>(foot)];
    return 0.5 * (w.at(f, leg.ankle) + w.at(f, leg.toe));
}

// Footholds in walking order with their treads; fills stairs.start_m and stairs.steps.
std::vector<Hold> place_footholds(const JointSequence& w, Staircase& stairs) {
    std::vector<Hold> holds;
    for (const StancePhase& p : detect_stance_phases(w)) {
        Hold h{p};
        for (int f = p.first_frame; f <= p.last_frame; ++f) h.along += stairs.along(foot_middle(w, f, p.foot));
        h.along /= p.last_frame - p.first_frame + 1;
        holds.push_back(h);
    }
    if (holds.size() < 4)
        throw Error("walk_to_stairs", "walk", "at least four stance phases", std::to_string(holds.size()));
    std::stable_sort(holds.begin(), holds.end(), [](const Hold& a, const Hold& b) { return a.along < b.along; });
    for (size_t i = 1; i < holds.size(); ++i) {
        const bool next_tread = holds[i].along - holds[i - 1].along >= kSideBySide;
        // By middle frame: a stance cut by the clip's start or end still orders right.
        const StancePhase &a = holds[i - 1].phase, &b = holds[i].phase;
        if (next_tread && b.first_frame + b.last_frame <= a.first_frame + a.last_frame)
            throw Error("walk_to_stairs", "walk",
                        "footholds that advance along the walking direction in time order (no turns)");
        holds[i].tread = holds[i - 1].tread + (next_tread ? 1 : 0);
    }
    stairs.steps = holds.back().tread;
    stairs.start_m = holds.front().along - 0.5 * stairs.going_m;
    for (Hold& h : holds) {
        h.shift = stairs.start_m + (h.tread + 0.5) * stairs.going_m - h.along;
        h.height = stairs.tread_height(h.tread);
    }
    std::stable_sort(holds.begin(), holds.end(),
                     [](const Hold& a, const Hold& b) { return a.phase.first_frame < b.phase.first_frame; });
    return holds;
}

// Where one foot goes at each frame: moved `shift` along the walk and up `height` (without the swing lift),
// plus `lift` (m) straight up.
struct FootPath {
    std::vector<double> shift, height, lift;
};

// The foot's progress through a swing from the source's own ankle motion along the walk, in [0, 1].
double swing_progress(const JointSequence& w, const Staircase& s, int ankle, int f, int from, int to) {
    const double a0 = s.along(w.at(from, ankle)), a1 = s.along(w.at(to, ankle));
    if (std::abs(a1 - a0) < 0.05) return min_jerk(static_cast<double>(f - from) / (to - from));  // a shuffle
    return std::clamp((s.along(w.at(f, ankle)) - a0) / (a1 - a0), 0.0, 1.0);
}

// Up or down between two treads: ascending feet rise early (before the nosing ahead), descending feet drop late
// (after they are past the nosing they leave).
double vertical_blend(double tau, double from_height, double to_height) {
    if (to_height > from_height) return min_jerk(tau / 0.6);
    if (to_height < from_height) return min_jerk((tau - 0.4) / 0.6);
    return 0.0;
}

void plan_swing(const JointSequence& w, const Staircase& s, Foot foot, const Hold& a, const Hold& b, double clearance,
                FootPath& path) {
    const LegJoints& leg = kLegs[static_cast<size_t>(foot)];
    const int from = a.phase.last_frame, to = b.phase.first_frame;
    double lift = 0;  // smallest lift so that y >= surface + clearance * sin(pi tau) for ankle and toe
    for (int f = from + 1; f < to; ++f) {
        const double tau = static_cast<double>(f - from) / (to - from), bump = std::sin(kPi * tau);
        const size_t i = static_cast<size_t>(f);
        path.shift[i] = a.shift + (b.shift - a.shift) * swing_progress(w, s, leg.ankle, f, from, to);
        path.height[i] = a.height + (b.height - a.height) * vertical_blend(tau, a.height, b.height);
        for (int j : {leg.ankle, leg.toe}) {
            const Vector3d moved = w.at(f, j) + path.shift[i] * s.direction;
            lift = std::max(lift, clearance + (s.height_at(moved) - moved.y() - path.height[i]) / bump);
        }
    }
    for (int f = from + 1; f < to; ++f)
        path.lift[static_cast<size_t>(f)] = lift * std::sin(kPi * (f - from) / (to - from));
}

FootPath plan_foot(const JointSequence& w, const Staircase& s, const std::vector<Hold>& holds, Foot foot,
                   double clearance) {
    const size_t n = static_cast<size_t>(w.num_frames);
    FootPath path{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
    const Hold* previous = nullptr;
    for (const Hold& h : holds) {
        if (h.phase.foot != foot) continue;
        for (int f = h.phase.first_frame; f <= h.phase.last_frame; ++f) {
            path.shift[static_cast<size_t>(f)] = h.shift;
            path.height[static_cast<size_t>(f)] = h.height;
        }
        if (previous) plan_swing(w, s, foot, *previous, h, clearance, path);
        previous = &h;
    }
    // Outside its first and last footholds (trimmed away later, but inside the smoothing of the body's
    // height) the foot stays where they put it.
    const auto it = std::find_if(holds.begin(), holds.end(), [&](const Hold& h) { return h.phase.foot == foot; });
    if (it == holds.end()) return path;
    for (int f = 0; f < it->phase.first_frame; ++f)
        path.shift[static_cast<size_t>(f)] = it->shift, path.height[static_cast<size_t>(f)] = it->height;
    for (size_t f = static_cast<size_t>(previous->phase.last_frame) + 1; f < n; ++f)
        path.shift[f] = previous->shift, path.height[f] = previous->height;
    return path;
}

// The frames in which both feet are between two footholds (or on one): [first, last].
std::pair<int, int> covered_frames(const std::vector<Hold>& holds) {
    std::array<int, 2> first{-1, -1}, last{-1, -1};
    for (const Hold& h : holds) {
        const size_t k = static_cast<size_t>(h.phase.foot);
        if (first[k] < 0) first[k] = h.phase.first_frame;
        last[k] = std::max(last[k], h.phase.last_frame);
    }
    if (first[0] < 0 || first[1] < 0) throw Error("walk_to_stairs", "walk", "stance phases of both feet");
    return {std::max(first[0], first[1]), std::min(last[0], last[1])};
}

// Least-squares line new = a + c * old through the footholds' positions along the walk: the body's progress.
std::pair<double, double> progress_map(const std::vector<Hold>& holds) {
    double mx = 0, my = 0;
    for (const Hold& h : holds) mx += h.along, my += h.along + h.shift;
    mx /= holds.size(), my /= holds.size();
    double sxx = 0, sxy = 0;
    for (const Hold& h : holds)
        sxx += (h.along - mx) * (h.along - mx), sxy += (h.along - mx) * (h.along + h.shift - my);
    const double c = sxy / sxx;
    return {my - c * mx, c};
}

// The body's mean facing over the walk (horizontal unit): across the hips and shoulders, turned to the front.
Vector3d mean_facing(const JointSequence& w) {
    Vector3d sum = Vector3d::Zero();
    for (int f = 0; f < w.num_frames; ++f) sum += body_facing(w, f);
    return horizontal_direction(sum);
}

// The staircase along the walk's travel from its first pelvis position; steps and start come with the footholds.
Staircase flight_along(const JointSequence& w, const StairOptions& o) {
    const Vector3d travel = w.at(w.num_frames - 1, smpl22::pelvis) - w.at(0, smpl22::pelvis);
    if (std::hypot(travel.x(), travel.z()) < kMinTravel)
        throw Error("walk_to_stairs", "walk", "a walk travelling at least 1.5 m",
                    std::to_string(std::hypot(travel.x(), travel.z())) + " m");
    Staircase stairs;
    stairs.origin = Vector3d(w.at(0, smpl22::pelvis).x(), 0, w.at(0, smpl22::pelvis).z());
    stairs.direction = horizontal_direction(travel);
    if (mean_facing(w).dot(stairs.direction) < 0.5)  // more than 60 deg off: sideways or backward
        throw Error("walk_to_stairs", "walk", "a walk facing the way it travels (not sideways or backward)");
    stairs.rise_m = o.rise_m, stairs.going_m = o.going_m, stairs.ascend = o.ascend;
    return stairs;
}

// The body's rise per frame: the mean of the two feet's foothold heights, smoothed over 0.3 s (a Gaussian of
// that sigma; 6 frames at 20 fps) so that it climbs through each step instead of jumping when a foot lands.
TimeSeries body_heights(const std::array<FootPath, 2>& feet, double fps) {
    const Eigen::Index n = static_cast<Eigen::Index>(feet[0].height.size());
    TimeSeries h(n, 1);
    for (Eigen::Index f = 0; f < n; ++f)
        h(f, 0) = 0.5 * (feet[0].height[static_cast<size_t>(f)] + feet[1].height[static_cast<size_t>(f)]);
    return gaussian_filter1d_nearest(h, 0.3 * fps);
}

JointSequence frame_range(const JointSequence& m, int first, int last) {
    JointSequence out(last - first + 1, m.num_joints, m.fps);
    std::copy(m.positions.begin() + static_cast<std::ptrdiff_t>(first) * m.num_joints,
              m.positions.begin() + static_cast<std::ptrdiff_t>(last + 1) * m.num_joints, out.positions.begin());
    return out;
}

}  // namespace

int Staircase::tread_at(const Vector3d& p) const {
    const double k = std::floor((along(p) - start_m) / going_m);
    return static_cast<int>(std::clamp(k, 0.0, static_cast<double>(steps)));
}

double Staircase::tread_height(int tread) const { return (ascend ? tread : steps - tread) * rise_m; }

double Staircase::along(const Vector3d& p) const {
    return (p.x() - origin.x()) * direction.x() + (p.z() - origin.z()) * direction.z();
}

StairOptions default_stair_options(bool ascend) {
    StairOptions o;
    o.ascend = ascend;
    o.trunk_lean_rad = ascend ? 0.12 : 0.05;
    o.cadence_factor = ascend ? 0.72 : 0.76;
    return o;
}

void validate(const StairOptions& o) {
    check_option_range(o.rise_m, 0.0, 0.22, "stair options", "rise_m");
    check_option_range(o.going_m, 0.22, 0.35, "stair options", "going_m");
    check_option_range(o.trunk_lean_rad, 0.0, 0.35, "stair options", "trunk_lean_rad");
    check_option_range(o.cadence_factor, 0.5, 1.0, "stair options", "cadence_factor");
    check_option_range(o.swing_clearance_m, 0.01, 0.10, "stair options", "swing_clearance_m");
}

StairMotion derive_stairs(const JointSequence& walk, const StairOptions& o) {
    validate(o);
    if (walk.num_joints != smpl22::kNumJoints || walk.num_frames < 3)
        throw Error("walk_to_stairs", "walk", "22 SMPL joints and at least 3 frames");
    const BoneLengths lengths = bone_lengths(walk, 0);
    const JointSequence w = retime(walk, o.cadence_factor);

    StairMotion out;
    Staircase& stairs = out.stairs = flight_along(w, o);
    const std::vector<Hold> holds = place_footholds(w, stairs);

    const std::array<FootPath, 2> feet = {plan_foot(w, stairs, holds, Foot::left, o.swing_clearance_m),
                                          plan_foot(w, stairs, holds, Foot::right, o.swing_clearance_m)};
    const auto [first, last] = covered_frames(holds);
    if (last - first < 2) throw Error("walk_to_stairs", "walk", "both feet stepping for at least 3 frames");
    const auto [offset, scale] = progress_map(holds);
    const TimeSeries body_height = body_heights(feet, w.fps);

    const JointSequence source = frame_range(w, first, last);
    JointSequence& m = out.motion = source;
    for (int g = 0; g < m.num_frames; ++g) {
        const int f = g + first;
        const size_t i = static_cast<size_t>(f);
        const double pelvis_along = stairs.along(w.at(f, smpl22::pelvis));
        const Vector3d body_move =
            (offset + (scale - 1) * pelvis_along) * stairs.direction + body_height(f, 0) * Vector3d::UnitY();
        for (int j = 0; j < m.num_joints; ++j)
            if (!is_leg_joint(j)) m.at(g, j) += body_move;
        for (size_t k = 0; k < 2; ++k) {
            const Vector3d foot_move =
                feet[k].shift[i] * stairs.direction + (feet[k].height[i] + feet[k].lift[i]) * Vector3d::UnitY();
            m.at(g, kLegs[k].ankle) += foot_move;
            m.at(g, kLegs[k].toe) += foot_move;
        }
        flex_trunk(m, g, stairs.direction, o.trunk_lean_rad);
    }
    lower_to_reach(m, reach_limits(source, lengths));
    place_knees(m, source, stairs.direction, lengths);

    for (const Hold& h : holds) {
        const int a = std::max(h.phase.first_frame, first) - first, b = std::min(h.phase.last_frame, last) - first;
        if (a <= b) out.footholds.push_back({h.phase.foot, a, b, h.tread});
    }
    return out;
}

JointSequence walk_to_stairs(const JointSequence& walk, const StairOptions& o) { return derive_stairs(walk, o).motion; }

}  // namespace t2imu
