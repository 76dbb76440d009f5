#include "motion/sit_to_stand.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "motion/motion_edit.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

using Eigen::Vector3d;
using namespace smpl22;

namespace {

// How far the pelvis is from standing toward the seat (horizontal and vertical, 0 standing .. 1 seated) and how
// far the trunk is bent (rad) at one frame.
struct Posture {
    double back = 0, down = 0, trunk = 0;
};

// A rise to `peak` from `start` to `top`, then a return to 0 at `end` (fractions of a phase).
double bend(double tau, double start, double top, double end, double peak) {
    return peak * (tau < top ? min_jerk((tau - start) / (top - start)) : 1 - min_jerk((tau - top) / (end - top)));
}

Posture sitting_down(double tau, double peak) {
    return {min_jerk(tau / 0.75), min_jerk((tau - 0.10) / 0.85), bend(tau, 0.05, 0.55, 1.0, peak)};
}

Posture standing_up(double tau, double peak) {
    return {1 - min_jerk((tau - 0.25) / 0.50), 1 - min_jerk((tau - 0.35) / 0.55), bend(tau, 0.0, 0.35, 0.80, peak)};
}

Posture posture_at(int f, const ChairOptions& o, double fps) {
    const int down_from = frames_of(o.stand_before_s, fps);
    const int seated_from = down_from + frames_of(o.sit_down_s, fps);
    const int up_from = seated_from + frames_of(o.seated_s, fps);
    const int standing_from = up_from + frames_of(o.stand_up_s, fps);
    if (f < down_from || f >= standing_from) return {};
    if (f < seated_from)
        return sitting_down(static_cast<double>(f - down_from) / (seated_from - down_from), o.trunk_flexion_peak_rad);
    if (f < up_from) return {1, 1, 0};
    return standing_up(static_cast<double>(f - up_from) / (standing_from - up_from), o.trunk_flexion_peak_rad);
}

// The seated pelvis: at seat height + pelvis_above_seat_m, as far behind the ankles as puts each knee straight
// above its ankle with the thigh at its length (the mean of both legs), beside the standing pelvis of frame 0.
Vector3d seated_pelvis(const JointSequence& s, const ChairOptions& o, const Vector3d& forward, const BoneLengths& len) {
    const Vector3d hips = 0.5 * (s.at(0, left_hip) + s.at(0, right_hip)) - s.at(0, pelvis);
    const Vector3d ankles = 0.5 * (s.at(0, left_ankle) + s.at(0, right_ankle));
    const double thigh = 0.5 * (len[left_knee] + len[right_knee]), shank = 0.5 * (len[left_ankle] + len[right_ankle]);
    const double pelvis_height = o.seat_height_m + o.pelvis_above_seat_m;
    const double rise = pelvis_height + hips.y() - (ankles.y() + shank);  // hip above knee
    if (std::abs(rise) >= thigh)
        throw Error("stand_sit_stand", "seat_height_m", "a seat the thighs reach with the shanks vertical");
    const double behind = std::sqrt(thigh * thigh - rise * rise) + hips.dot(forward);
    const Vector3d p0 = s.at(0, pelvis);
    const double shift = (ankles - p0).dot(forward) - behind;  // along forward, from the standing pelvis
    Vector3d seat = p0 + shift * forward;
    seat.y() = pelvis_height;
    return seat;
}

}  // namespace

void validate(const ChairOptions& o) {
    check_option_range(o.seat_height_m, 0.25, 0.60, "chair options", "seat_height_m");
    check_option_range(o.pelvis_above_seat_m, 0.05, 0.15, "chair options", "pelvis_above_seat_m");
    check_option_range(o.stand_before_s, 0.0, 10.0, "chair options", "stand_before_s");
    check_option_range(o.sit_down_s, 1.0, 4.0, "chair options", "sit_down_s");
    check_option_range(o.seated_s, 0.5, 60.0, "chair options", "seated_s");
    check_option_range(o.stand_up_s, 1.0, 4.0, "chair options", "stand_up_s");
    check_option_range(o.stand_after_s, 0.0, 10.0, "chair options", "stand_after_s");
    check_option_range(o.trunk_flexion_peak_rad, 0.2, 1.0, "chair options", "trunk_flexion_peak_rad");
}

int stand_sit_stand_frames(const ChairOptions& o, double fps) {
    return frames_of(o.stand_before_s, fps) + frames_of(o.sit_down_s, fps) + frames_of(o.seated_s, fps) +
           frames_of(o.stand_up_s, fps) + frames_of(o.stand_after_s, fps) + 1;
}

JointSequence stand_sit_stand(const JointSequence& standing, const ChairOptions& o) {
    validate(o);
    if (standing.num_joints != kNumJoints) throw Error("stand_sit_stand", "standing", "22 SMPL joints");
    const int n = stand_sit_stand_frames(o, standing.fps);
    if (standing.num_frames < n)
        throw Error("stand_sit_stand", "standing", "at least " + std::to_string(n) + " frames",
                    std::to_string(standing.num_frames));
    for (int f = 1; f < n; ++f) {
        const Vector3d drift = standing.at(f, pelvis) - standing.at(0, pelvis);
        if (std::hypot(drift.x(), drift.z()) > kMaxStandingDriftM) {
            char expected[96];
            std::snprintf(expected, sizeof expected,
                          "a pelvis within %.2f m of where it stands at frame 0, horizontally", kMaxStandingDriftM);
            throw Error("stand_sit_stand", "standing", expected, "moves away at frame " + std::to_string(f));
        }
    }
    const BoneLengths lengths = bone_lengths(standing, 0);
    const Vector3d forward = body_facing(standing, 0);
    const Vector3d seat = seated_pelvis(standing, o, forward, lengths);

    JointSequence source(n, kNumJoints, standing.fps);
    std::copy(standing.positions.begin(), standing.positions.begin() + static_cast<std::ptrdiff_t>(n) * kNumJoints,
              source.positions.begin());
    JointSequence m = source;
    for (int f = 0; f < n; ++f) {
        const Posture p = posture_at(f, o, standing.fps);
        const Vector3d to_seat = seat - source.at(f, pelvis);
        const Vector3d move(p.back * to_seat.x(), p.down * to_seat.y(), p.back * to_seat.z());
        for (int j = 0; j < kNumJoints; ++j)
            if (!is_leg_joint(j)) m.at(f, j) += move;
        for (const LegJoints& leg : kLegs) {  // planted where they stand at the start
            m.at(f, leg.ankle) = source.at(0, leg.ankle);
            m.at(f, leg.toe) = source.at(0, leg.toe);
        }
        flex_trunk(m, f, forward, p.trunk);
    }
    lower_to_reach(m, reach_limits(source, lengths));
    place_knees(m, source, forward, lengths);
    return m;
}

}  // namespace t2imu
