#include "motion/motion_attributes.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/error.hpp"
#include "core/number_text.hpp"
#include "motion/foot_contacts.hpp"
#include "motion/foot_landings.hpp"
#include "motion/motion_descriptors.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

const char* posture_name(Posture p) {
    switch (p) {
        case Posture::standing: return "standing";
        case Posture::seated: return "seated";
        case Posture::lying: return "lying";
    }
    return "standing";
}

const char* travel_direction_name(TravelDirection d) {
    switch (d) {
        case TravelDirection::none: return "none";
        case TravelDirection::forward: return "forward";
        case TravelDirection::backward: return "backward";
        case TravelDirection::left: return "left";
        case TravelDirection::right: return "right";
    }
    return "none";
}

const char* lying_side_name(LyingSide s) {
    switch (s) {
        case LyingSide::none: return "none";
        case LyingSide::back: return "back";
        case LyingSide::front: return "front";
        case LyingSide::left: return "left";
        case LyingSide::right: return "right";
    }
    return "none";
}

const char* transition_name(Transition t) {
    switch (t) {
        case Transition::sit_down: return "sit_down";
        case Transition::stand_up: return "stand_up";
        case Transition::lie_down: return "lie_down";
        case Transition::get_up: return "get_up";
        case Transition::climb_up: return "climb_up";
        case Transition::climb_down: return "climb_down";
    }
    return "sit_down";
}

namespace {

using Eigen::Vector3d;
constexpr double kDegrees = 180.0 / M_PI;
constexpr double kLyingHeadAbovePelvis = 0.3;  // m: upright about 0.6
constexpr double kSeatedThighTilt = 55.0;      // degrees from vertical: about 0 standing, 90 on a chair
constexpr double kSeatedPelvisHeight = 0.7;    // m above the lowest joint: about 0.95 standing, 0.5 on a chair

double wrap_angle(double a) { return std::remainder(a, 2 * M_PI); }

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    const size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<long>(mid), v.end());
    double m = v[mid];
    if (v.size() % 2 == 0) m = (m + *std::max_element(v.begin(), v.begin() + static_cast<long>(mid))) / 2;
    return m;
}

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const double pos = q * static_cast<double>(v.size() - 1);
    const size_t lo = static_cast<size_t>(std::floor(pos)), hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

int half_window(double seconds, double fps) { return std::max(0, static_cast<int>(std::lround(seconds * fps / 2))); }

// Centred moving average whose half-width shrinks near the ends, so a path at constant velocity stays exact.
std::vector<double> centred_average(const std::vector<double>& x, int half) {
    const int n = static_cast<int>(x.size());
    std::vector<double> out(x.size());
    for (int f = 0; f < n; ++f) {
        const int h = std::min({half, f, n - 1 - f});
        double s = 0;
        for (int g = f - h; g <= f + h; ++g) s += x[static_cast<size_t>(g)];
        out[static_cast<size_t>(f)] = s / (2 * h + 1);
    }
    return out;
}

// Central difference (one-sided at the ends), per second.
std::vector<double> rate_of(const std::vector<double>& x, double fps) {
    const size_t n = x.size();
    std::vector<double> d(n, 0.0);
    for (size_t f = 0; f < n; ++f) {
        const size_t a = f == 0 ? 0 : f - 1, b = std::min(n - 1, f + 1);
        if (b > a) d[f] = (x[b] - x[a]) * fps / static_cast<double>(b - a);
    }
    return d;
}

struct Path {
    std::vector<double> x, z;    // smoothed pelvis position, m
    std::vector<double> vx, vz;  // its velocity, m/s
};

Path smoothed_pelvis_path(const JointSequence& m) {
    std::vector<double> x, z;
    for (int f = 0; f < m.num_frames; ++f)
        x.push_back(m.at(f, smpl22::pelvis).x()), z.push_back(m.at(f, smpl22::pelvis).z());
    Path p;
    const int half = half_window(kSmoothingSeconds, m.fps);
    p.x = centred_average(x, half), p.z = centred_average(z, half);
    p.vx = rate_of(p.x, m.fps), p.vz = rate_of(p.z, m.fps);
    return p;
}

// Unwrapped heading per frame (rad, + left): the facing across hips and shoulders; a frame whose across line is
// vertical (lying on the side) keeps the heading before it.
std::vector<double> unwrapped_heading(const JointSequence& m) {
    std::vector<double> h(static_cast<size_t>(m.num_frames), 0.0);
    double last = 0;
    bool have = false;
    for (int f = 0; f < m.num_frames; ++f) {
        const Vector3d across = (m.at(f, smpl22::left_hip) - m.at(f, smpl22::right_hip)) +
                                (m.at(f, smpl22::left_shoulder) - m.at(f, smpl22::right_shoulder));
        const double fx = -across.z(), fz = across.x();  // across x up: the facing
        double a = last;
        if (std::hypot(fx, fz) > 1e-6) {
            a = std::atan2(fx, fz);
            if (have) a = last + wrap_angle(a - last);
            have = true;
        }
        h[static_cast<size_t>(f)] = last = a;
    }
    return h;
}

double mean_of_range(const std::vector<double>& v, size_t begin, size_t end) {
    double s = 0;
    for (size_t i = begin; i < end; ++i) s += v[i];
    return end > begin ? s / static_cast<double>(end - begin) : 0.0;
}

struct Travel {
    double path_turn = 0;  // rad
    TravelDirection direction = TravelDirection::none;
};

Travel travel_of(const Path& p, const std::vector<double>& heading, double fps) {
    Travel t;
    std::array<int, 5> votes{};
    bool have = false;
    double last = 0;
    int moving = 0;
    for (size_t f = 0; f < p.vx.size(); ++f) {
        if (std::hypot(p.vx[f], p.vz[f]) < kTravelSpeed) continue;
        const double dir = std::atan2(p.vx[f], p.vz[f]);
        if (have) t.path_turn += wrap_angle(dir - last);
        last = dir, have = true, ++moving;
        const double rel = wrap_angle(dir - heading[f]) * kDegrees;
        const TravelDirection d = std::abs(rel) <= 45    ? TravelDirection::forward
                                  : std::abs(rel) >= 135 ? TravelDirection::backward
                                  : rel > 0              ? TravelDirection::left
                                                         : TravelDirection::right;
        ++votes[static_cast<size_t>(d)];
    }
    if (moving >= std::max(2.0, kMinPostureSeconds * fps))
        t.direction = static_cast<TravelDirection>(std::max_element(votes.begin(), votes.end()) - votes.begin());
    return t;
}

double thigh_tilt_deg(const JointSequence& m, int f) {
    double sum = 0;
    for (const auto& [hip, knee] :
         {std::pair{smpl22::left_hip, smpl22::left_knee}, std::pair{smpl22::right_hip, smpl22::right_knee}}) {
        const Vector3d up = m.at(f, hip) - m.at(f, knee);
        sum += std::acos(std::clamp(up.y() / std::max(up.norm(), 1e-9), -1.0, 1.0)) * kDegrees;
    }
    return sum / 2;
}

double lowest_foot(const JointSequence& m, int f) {
    double low = m.at(f, smpl22::left_ankle).y();
    for (int j : {smpl22::left_foot, smpl22::right_ankle, smpl22::right_foot}) low = std::min(low, m.at(f, j).y());
    return low;
}

struct Foothold {
    int frame;  // the middle of its planted phase
    double height;
};

std::vector<Foothold> footholds(const JointSequence& m) {
    std::vector<Foothold> out;
    for (const StancePhase& s : detect_planted_phases(m)) {
        const auto& joints = s.foot == Foot::left ? smpl22::kFootLeft : smpl22::kFootRight;
        double h = 0;
        for (int f = s.first_frame; f <= s.last_frame; ++f)
            h += std::min(m.at(f, joints[0]).y(), m.at(f, joints[1]).y());
        out.push_back({(s.first_frame + s.last_frame) / 2, h / (s.last_frame - s.first_frame + 1)});
    }
    // In placing order: by the middle of each phase, since a clip cut mid-stance starts (or ends) both feet at once.
    std::stable_sort(out.begin(), out.end(), [](const Foothold& a, const Foothold& b) { return a.frame < b.frame; });
    return out;
}

void measure_steps(const JointSequence& m, MotionAttributes& a, std::vector<std::pair<int, Transition>>& events) {
    const std::vector<Foothold> holds = footholds(m);
    if (holds.size() >= 2)
        a.rise_m = holds.back().height - holds.front().height;
    else
        a.rise_m = m.at(m.num_frames - 1, smpl22::pelvis).y() - m.at(0, smpl22::pelvis).y();
    double total = 0;
    int run_sign = 0, run_steps = 0, run_start = 0;
    auto close_run = [&]() {
        if (run_sign != 0 && run_steps >= 2)
            events.push_back({run_start, run_sign > 0 ? Transition::climb_up : Transition::climb_down});
    };
    for (size_t i = 1; i < holds.size(); ++i) {
        const double d = holds[i].height - holds[i - 1].height;
        if (std::abs(d) <= kTreadRise) continue;
        const int sign = d > 0 ? 1 : -1;
        (sign > 0 ? a.steps_up : a.steps_down) += 1;
        total += std::abs(d);
        if (sign != run_sign) close_run(), run_sign = sign, run_steps = 0, run_start = holds[i].frame;
        ++run_steps;
    }
    close_run();
    const int steps = a.steps_up + a.steps_down;
    a.step_height_m = steps > 0 ? total / steps : 0.0;
}

void measure_jumps(const JointSequence& m, const std::vector<Posture>& posture, MotionAttributes& a) {
    const int n = m.num_frames, window = std::max(1, static_cast<int>(std::lround(m.fps)));
    std::vector<double> low(static_cast<size_t>(n)), floor(static_cast<size_t>(n)), rise(static_cast<size_t>(n));
    for (int f = 0; f < n; ++f) low[static_cast<size_t>(f)] = lowest_foot(m, f);
    std::vector<double> grounded;
    for (int f = 0; f < n; ++f) {
        double before = low[static_cast<size_t>(f)], after = before;
        for (int g = std::max(0, f - window); g < f; ++g) before = std::min(before, low[static_cast<size_t>(g)]);
        for (int g = f + 1; g <= std::min(n - 1, f + window); ++g) after = std::min(after, low[static_cast<size_t>(g)]);
        floor[static_cast<size_t>(f)] = std::max(before, after);  // the floor a climbing foot stands on (descriptors)
        rise[static_cast<size_t>(f)] = m.at(f, smpl22::pelvis).y() - floor[static_cast<size_t>(f)];
        if (posture[static_cast<size_t>(f)] == Posture::standing &&
            low[static_cast<size_t>(f)] - floor[static_cast<size_t>(f)] <= kAirborneHeight)
            grounded.push_back(rise[static_cast<size_t>(f)]);
    }
    if (grounded.empty()) return;
    const double standing = median(grounded);
    double heights = 0;
    for (int f = 0; f < n;) {
        if (low[static_cast<size_t>(f)] - floor[static_cast<size_t>(f)] <= kAirborneHeight) {
            ++f;
            continue;
        }
        double peak = -1e9;
        for (; f < n && low[static_cast<size_t>(f)] - floor[static_cast<size_t>(f)] > kAirborneHeight; ++f)
            peak = std::max(peak, rise[static_cast<size_t>(f)]);
        if (peak - standing > kJumpRise) ++a.jumps, heights += peak - standing;
    }
    a.jump_height_m = a.jumps > 0 ? heights / a.jumps : 0.0;
}

LyingSide lying_side_of(const JointSequence& m, const std::vector<Posture>& posture) {
    Vector3d front = Vector3d::Zero();
    double left_height = 0;
    int count = 0;
    for (int f = 0; f < m.num_frames; ++f) {
        if (posture[static_cast<size_t>(f)] != Posture::lying) continue;
        const Vector3d left = (m.at(f, smpl22::left_hip) - m.at(f, smpl22::right_hip)).normalized();
        const Vector3d up = (m.at(f, smpl22::neck) - m.at(f, smpl22::pelvis)).normalized();
        front += left.cross(up).normalized();  // left x up: the belly's direction (standing: +Z)
        left_height += left.y();
        ++count;
    }
    if (count < std::max(1.0, kMinPostureSeconds * m.fps)) return LyingSide::none;
    front /= count;
    if (front.y() > 0.5) return LyingSide::back;
    if (front.y() < -0.5) return LyingSide::front;
    return left_height < 0 ? LyingSide::left : LyingSide::right;
}

}  // namespace

std::vector<Posture> posture_per_frame(const JointSequence& m) {
    const int n = m.num_frames;
    std::vector<Posture> p(static_cast<size_t>(n), Posture::standing);
    for (int f = 0; f < n; ++f) {
        const Vector3d& pelvis = m.at(f, smpl22::pelvis);
        if (m.at(f, smpl22::head).y() - pelvis.y() < kLyingHeadAbovePelvis)
            p[static_cast<size_t>(f)] = Posture::lying;
        else if (thigh_tilt_deg(m, f) > kSeatedThighTilt &&
                 pelvis.y() - lowest_joint_height_at(m, f) < kSeatedPelvisHeight)
            p[static_cast<size_t>(f)] = Posture::seated;
    }
    // Short runs join the run before them (the first run the one after), so a stumble is not a sit.
    const int shortest = std::max(1, static_cast<int>(std::lround(kMinPostureSeconds * m.fps)));
    for (bool changed = true; changed;) {
        changed = false;
        for (int f = 0; f < n;) {
            int g = f;
            while (g < n && p[static_cast<size_t>(g)] == p[static_cast<size_t>(f)]) ++g;
            if (g - f < shortest && !(f == 0 && g == n)) {
                const Posture with = f > 0 ? p[static_cast<size_t>(f - 1)] : p[static_cast<size_t>(g)];
                std::fill(p.begin() + f, p.begin() + g, with);
                changed = true;
            }
            f = g;
        }
    }
    return p;
}

std::vector<double> ground_speed_per_frame(const JointSequence& m) {
    const Path p = smoothed_pelvis_path(m);
    std::vector<double> s(p.vx.size());
    for (size_t f = 0; f < s.size(); ++f) s[f] = std::hypot(p.vx[f], p.vz[f]);
    return s;
}

MotionAttributes measure_attributes(const JointSequence& m, const std::string& source) {
    if (m.num_joints != smpl22::kNumJoints || m.num_frames < 3)
        throw Error(source, "joints", "22 joints and at least 3 frames");
    MotionAttributes a;
    const size_t n = static_cast<size_t>(m.num_frames);
    a.duration_s = (m.num_frames - 1) / m.fps;

    const Path path = smoothed_pelvis_path(m);
    a.ground_speed_m_s = median(ground_speed_per_frame(m));
    for (size_t f = 1; f < n; ++f) a.distance_m += std::hypot(path.x[f] - path.x[f - 1], path.z[f] - path.z[f - 1]);
    a.cadence_steps_min = a.duration_s > 0 ? detect_landings(m).size() / a.duration_s * 60 : 0;
    a.stride_length_m = a.cadence_steps_min > 0 ? 2 * a.ground_speed_m_s / (a.cadence_steps_min / 60) : 0;

    const std::vector<double> heading = centred_average(unwrapped_heading(m), half_window(0.5, m.fps));
    const size_t edge = std::clamp<size_t>(static_cast<size_t>(std::lround(0.5 * m.fps)), 1, n);
    a.heading_change_deg = (mean_of_range(heading, n - edge, n) - mean_of_range(heading, 0, edge)) * kDegrees;
    for (size_t f = 1; f < n; ++f) a.turning_deg += std::abs(heading[f] - heading[f - 1]) * kDegrees;
    const Travel travel = travel_of(path, heading, m.fps);
    a.path_turn_deg = travel.path_turn * kDegrees;
    a.travel = travel.direction;

    const std::vector<Posture> posture = posture_per_frame(m);
    std::vector<double> lean;
    std::array<std::vector<double>, 2> wrist_along;
    for (size_t f = 0; f < n; ++f) {
        const int i = static_cast<int>(f);
        const Vector3d facing(std::sin(heading[f]), 0, std::cos(heading[f]));
        const Vector3d& pelvis = m.at(i, smpl22::pelvis);
        wrist_along[0].push_back((m.at(i, smpl22::left_wrist) - pelvis).dot(facing));
        wrist_along[1].push_back((m.at(i, smpl22::right_wrist) - pelvis).dot(facing));
        if (posture[f] == Posture::lying) continue;
        const Vector3d trunk = m.at(i, smpl22::neck) - pelvis;
        lean.push_back(std::atan2(trunk.dot(facing), trunk.y()) * kDegrees);
        if (posture[f] == Posture::seated) a.seated_s += 1 / m.fps;
    }
    for (const auto& w : wrist_along) a.arm_swing_m += (percentile(w, 0.95) - percentile(w, 0.05)) / 2;
    a.trunk_lean_deg = mean_of_range(lean, 0, lean.size());
    for (Posture p : posture) a.lying_s += p == Posture::lying ? 1 / m.fps : 0;
    a.lying_side = lying_side_of(m, posture);

    std::vector<std::pair<int, Transition>> events;
    for (size_t f = 1; f < n; ++f) {
        const Posture from = posture[f - 1], to = posture[f];
        if (from == to) continue;
        const int i = static_cast<int>(f);
        if (to == Posture::lying)
            events.push_back({i, Transition::lie_down});
        else if (from == Posture::lying)
            events.push_back({i, Transition::get_up});
        else
            events.push_back({i, to == Posture::seated ? Transition::sit_down : Transition::stand_up});
    }
    measure_steps(m, a, events);
    measure_jumps(m, posture, a);
    std::stable_sort(events.begin(), events.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& e : events) a.transitions.push_back(e.second);
    return a;
}

std::vector<std::pair<std::string, std::string>> attribute_fields(const MotionAttributes& a) {
    const auto num = [](double v, int decimals) { return fixed_text(v, decimals); };
    std::string transitions;
    for (Transition t : a.transitions)
        transitions += (transitions.empty() ? "" : "+") + std::string(transition_name(t));
    return {{"duration_s", num(a.duration_s, 2)},
            {"ground_speed_m_s", num(a.ground_speed_m_s, 3)},
            {"distance_m", num(a.distance_m, 2)},
            {"cadence_steps_min", num(a.cadence_steps_min, 1)},
            {"stride_length_m", num(a.stride_length_m, 2)},
            {"heading_change_deg", num(a.heading_change_deg, 1)},
            {"turning_deg", num(a.turning_deg, 1)},
            {"path_turn_deg", num(a.path_turn_deg, 1)},
            {"travel", travel_direction_name(a.travel)},
            {"arm_swing_m", num(a.arm_swing_m, 3)},
            {"trunk_lean_deg", num(a.trunk_lean_deg, 1)},
            {"rise_m", num(a.rise_m, 2)},
            {"steps_up", std::to_string(a.steps_up)},
            {"steps_down", std::to_string(a.steps_down)},
            {"step_height_m", num(a.step_height_m, 3)},
            {"jumps", std::to_string(a.jumps)},
            {"jump_height_m", num(a.jump_height_m, 3)},
            {"seated_s", num(a.seated_s, 2)},
            {"lying_s", num(a.lying_s, 2)},
            {"lying_side", lying_side_name(a.lying_side)},
            {"transitions", transitions}};
}

}  // namespace t2imu
