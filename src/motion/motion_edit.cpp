#include "motion/motion_edit.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/signal/gaussian_filter.hpp"
#include "motion/skeleton.hpp"
#include "motion/two_bone_ik.hpp"

namespace t2imu {

using Eigen::Vector3d;
using namespace smpl22;

const std::array<LegJoints, 2> kLegs = {
    {{left_hip, left_knee, left_ankle, left_foot}, {right_hip, right_knee, right_ankle, right_foot}}};

void check_option_range(double value, double lo, double hi, const char* options, const char* field) {
    if (!(value >= lo && value <= hi))
        throw Error(options, field, "in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]",
                    std::to_string(value));
}

BoneLengths bone_lengths(const JointSequence& m, int frame) {
    BoneLengths l{};
    for (int j = 1; j < kNumJoints; ++j)
        l[static_cast<size_t>(j)] = (m.at(frame, j) - m.at(frame, kParents[static_cast<size_t>(j)])).norm();
    return l;
}

double max_bone_length_error(const JointSequence& m, const BoneLengths& lengths) {
    double worst = 0;
    for (int f = 0; f < m.num_frames; ++f) {
        const BoneLengths l = bone_lengths(m, f);
        for (size_t j = 1; j < l.size(); ++j) worst = std::max(worst, std::abs(l[j] - lengths[j]));
    }
    return worst;
}

void restore_bone_lengths(JointSequence& m, const BoneLengths& lengths) {
    // Parents precede children in the SMPL-22 order, so each parent is final before its children are placed;
    // a child moves with its parent's shift before its own bone is rescaled.
    for (int f = 0; f < m.num_frames; ++f) {
        std::array<Vector3d, kNumJoints> shift;
        shift[0].setZero();
        for (int j = 1; j < kNumJoints; ++j) {
            const int p = kParents[static_cast<size_t>(j)];
            const Vector3d old_child = m.at(f, j) + shift[static_cast<size_t>(p)];
            const Vector3d bone = old_child - m.at(f, p);
            const Vector3d placed = m.at(f, p) + lengths[static_cast<size_t>(j)] * bone.normalized();
            shift[static_cast<size_t>(j)] = placed - m.at(f, j);
            m.at(f, j) = placed;
        }
    }
}

namespace {

// Slope at a sample from the secants either side (Fritsch & Butland 1984): 0 at a turn or a flat, else their
// harmonic mean, so the cubic between samples never overshoots them: a foot resting on the floor stays there.
double monotone_slope(double before, double after) {
    if (before * after <= 0) return 0.0;
    return 2.0 / (1.0 / before + 1.0 / after);
}

// Cubic Hermite between p1 and p2 at u in [0, 1], slopes per sample step, per coordinate.
Vector3d monotone_cubic(const Vector3d& p0, const Vector3d& p1, const Vector3d& p2, const Vector3d& p3, double u) {
    const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u), h01 = u * u * (3 - 2 * u),
                 h11 = u * u * (u - 1);
    Vector3d out;
    for (int c = 0; c < 3; ++c) {
        const double m1 = monotone_slope(p1[c] - p0[c], p2[c] - p1[c]),
                     m2 = monotone_slope(p2[c] - p1[c], p3[c] - p2[c]);
        out[c] = h00 * p1[c] + h10 * m1 + h01 * p2[c] + h11 * m2;
    }
    return out;
}

// restore_bone_lengths, then each ankle back where it was (knee by IK, toe carried along): restoring from the
// pelvis outward would otherwise slide a planted foot by the interpolation's small length errors.
void restore_lengths_keeping_ankles(JointSequence& m, const BoneLengths& lengths) {
    std::vector<Vector3d> ankles;
    for (int f = 0; f < m.num_frames; ++f)
        for (const LegJoints& leg : kLegs) ankles.push_back(m.at(f, leg.ankle));
    restore_bone_lengths(m, lengths);
    for (int f = 0; f < m.num_frames; ++f)
        for (size_t k = 0; k < 2; ++k) {
            const LegJoints& leg = kLegs[k];
            const TwoBoneIkResult ik = solve_two_bone_ik(m.at(f, leg.hip), ankles[static_cast<size_t>(2 * f) + k],
                                                         lengths[static_cast<size_t>(leg.knee)],
                                                         lengths[static_cast<size_t>(leg.ankle)], m.at(f, leg.knee));
            m.at(f, leg.knee) = ik.middle;
            m.at(f, leg.toe) += ik.end - m.at(f, leg.ankle);
            m.at(f, leg.ankle) = ik.end;
        }
}

}  // namespace

JointSequence retime(const JointSequence& m, double speed) {
    if (!(speed >= 0.25 && speed <= 4.0)) throw Error("retime", "speed", "in [0.25, 4]", std::to_string(speed));
    const int n = static_cast<int>(std::floor((m.num_frames - 1) / speed + 1e-9)) + 1;
    JointSequence out(n, m.num_joints, m.fps);
    auto clamp_frame = [&](int f) { return std::clamp(f, 0, m.num_frames - 1); };
    for (int g = 0; g < n; ++g) {
        const double t = g * speed;
        const int i = std::min(static_cast<int>(std::floor(t)), m.num_frames - 1);
        const double u = t - i;
        for (int j = 0; j < m.num_joints; ++j)
            out.at(g, j) = monotone_cubic(m.at(clamp_frame(i - 1), j), m.at(i, j), m.at(clamp_frame(i + 1), j),
                                          m.at(clamp_frame(i + 2), j), u);
    }
    if (m.num_joints == kNumJoints) restore_lengths_keeping_ankles(out, bone_lengths(m, 0));
    return out;
}

double min_jerk(double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x * x * x * (10 + x * (-15 + 6 * x));
}

Vector3d horizontal_direction(const Vector3d& v) {
    const Vector3d h(v.x(), 0, v.z());
    if (h.norm() < 1e-9) throw Error("motion editing", "direction", "a direction with a horizontal part");
    return h.normalized();
}

Vector3d body_facing(const JointSequence& m, int frame) {
    const Vector3d across =
        (m.at(frame, left_hip) - m.at(frame, right_hip)) + (m.at(frame, left_shoulder) - m.at(frame, right_shoulder));
    return horizontal_direction(across.cross(Vector3d::UnitY()));
}

JointSequence turned_to_face(const JointSequence& m, int frame, const Vector3d& facing, const Vector3d& pivot,
                             const Vector3d& to) {
    const Vector3d from = body_facing(m, frame);
    const double turn =
        std::atan2(facing.z(), facing.x()) - std::atan2(from.z(), from.x());  // in the x-z plane, x towards z
    const double c = std::cos(turn), s = std::sin(turn);
    JointSequence out = m;
    for (Vector3d& p : out.positions) {
        const double x = p.x() - pivot.x(), z = p.z() - pivot.z();
        p.x() = to.x() + c * x - s * z;
        p.z() = to.z() + s * x + c * z;
    }
    return out;
}

bool is_trunk_joint(int j) {
    while (j > 0 && j != spine1) j = kParents[static_cast<size_t>(j)];
    return j == spine1;
}

bool is_leg_joint(int j) {
    return j == left_knee || j == right_knee || j == left_ankle || j == right_ankle || j == left_foot ||
           j == right_foot;
}

void flex_trunk(JointSequence& m, int frame, const Vector3d& forward, double angle_rad) {
    // Around the body's left axis (up x forward) a positive angle turns up toward forward.
    const Eigen::Matrix3d r = Eigen::AngleAxisd(angle_rad, Vector3d::UnitY().cross(forward)).toRotationMatrix();
    const Vector3d pivot = m.at(frame, pelvis);
    for (int j = 0; j < m.num_joints; ++j)
        if (is_trunk_joint(j)) m.at(frame, j) = pivot + r * (m.at(frame, j) - pivot);
}

std::vector<double> upper_envelope(const std::vector<double>& x, int radius) {
    const int n = static_cast<int>(x.size());
    if (n == 0 || radius <= 0) return x;
    TimeSeries peak(n, 1);
    for (int i = 0; i < n; ++i) {
        double v = x[static_cast<size_t>(i)];
        for (int k = std::max(0, i - radius); k <= std::min(n - 1, i + radius); ++k)
            v = std::max(v, x[static_cast<size_t>(k)]);
        peak(i, 0) = v;
    }
    // radius = int(truncate * sigma + 0.5) with sigma = radius / 2 and truncate = 2.
    const TimeSeries smooth = gaussian_filter1d_nearest(peak, radius / 2.0, 2.0);
    std::vector<double> out(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) out[static_cast<size_t>(i)] = std::max(smooth(i, 0), x[static_cast<size_t>(i)]);
    return out;
}

std::array<double, 2> reach_limits(const JointSequence& source, const BoneLengths& lengths) {
    std::array<double, 2> reach{0, 0};
    for (int f = 0; f < source.num_frames; ++f)
        for (size_t leg = 0; leg < 2; ++leg)
            reach[leg] = std::max(reach[leg], (source.at(f, kLegs[leg].hip) - source.at(f, kLegs[leg].ankle)).norm());
    for (size_t leg = 0; leg < 2; ++leg)
        reach[leg] = std::min(reach[leg], 0.999 * (lengths[static_cast<size_t>(kLegs[leg].knee)] +
                                                   lengths[static_cast<size_t>(kLegs[leg].ankle)]));
    return reach;
}

namespace {

// How far the hip must drop (m, >= 0) to come within `reach` of the ankle, moving straight down.
double drop_to_reach(const Vector3d& hip, const Vector3d& ankle, double reach) {
    const Vector3d d = hip - ankle;
    if (d.norm() <= reach) return 0.0;
    const double horizontal = std::hypot(d.x(), d.z());
    // Out of reach even level with the ankle: come down to its height, where the IK stretches toward it.
    if (horizontal >= reach) return d.y();
    return d.y() - std::sqrt(reach * reach - horizontal * horizontal);
}

}  // namespace

double lower_to_reach(JointSequence& m, const std::array<double, 2>& reach_m) {
    std::vector<double> drop(static_cast<size_t>(m.num_frames), 0.0);
    for (int f = 0; f < m.num_frames; ++f)
        for (size_t leg = 0; leg < 2; ++leg)
            drop[static_cast<size_t>(f)] =
                std::max(drop[static_cast<size_t>(f)],
                         drop_to_reach(m.at(f, kLegs[leg].hip), m.at(f, kLegs[leg].ankle), reach_m[leg]));
    // 0.4 s either side (8 frames at 20 fps): the body sinks into a deep step instead of jerking down.
    const std::vector<double> smooth = upper_envelope(drop, std::max(1, frames_of(0.4, m.fps)));
    double most = 0;
    for (int f = 0; f < m.num_frames; ++f) {
        const double d = smooth[static_cast<size_t>(f)];
        most = std::max(most, d);
        for (int j = 0; j < m.num_joints; ++j)
            if (!is_leg_joint(j)) m.at(f, j).y() -= d;
    }
    return most;
}

bool place_knees(JointSequence& m, const JointSequence& source, const std::vector<Vector3d>& forward,
                 const BoneLengths& lengths) {
    if (source.num_frames != m.num_frames) throw Error("place_knees", "source", "as many frames as the motion");
    if (static_cast<int>(forward.size()) != m.num_frames)
        throw Error("place_knees", "forward", "one direction per frame");
    bool all = true;
    for (int f = 0; f < m.num_frames; ++f)
        for (const LegJoints& leg : kLegs) {
            const Vector3d hint = m.at(f, leg.hip) + (source.at(f, leg.knee) - source.at(f, leg.hip)) +
                                  kKneeHintPush * forward[static_cast<size_t>(f)];
            const TwoBoneIkResult ik =
                solve_two_bone_ik(m.at(f, leg.hip), m.at(f, leg.ankle), lengths[static_cast<size_t>(leg.knee)],
                                  lengths[static_cast<size_t>(leg.ankle)], hint);
            m.at(f, leg.knee) = ik.middle;
            m.at(f, leg.toe) += ik.end - m.at(f, leg.ankle);
            m.at(f, leg.ankle) = ik.end;
            all = all && ik.reached;
        }
    return all;
}

bool place_knees(JointSequence& m, const JointSequence& source, const Vector3d& forward, const BoneLengths& lengths) {
    return place_knees(m, source, std::vector<Vector3d>(static_cast<size_t>(m.num_frames), forward), lengths);
}

double knee_flexion_rad(const JointSequence& m, int frame, int leg) {
    const LegJoints& l = kLegs[static_cast<size_t>(leg)];
    const Vector3d thigh = m.at(frame, l.knee) - m.at(frame, l.hip);
    const Vector3d shank = m.at(frame, l.ankle) - m.at(frame, l.knee);
    return std::acos(std::clamp(thigh.normalized().dot(shank.normalized()), -1.0, 1.0));
}

}  // namespace t2imu
