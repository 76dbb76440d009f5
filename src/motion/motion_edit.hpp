// Building blocks of derived motion, edits of captured SMPL-22 joint positions (metres, Y up, floor at y = 0)
// that keep the skeleton rigid: bone lengths, retiming, trunk flexion about the pelvis, lowering the body so
// the legs reach the feet, and knees re-solved by two-bone IK. stair_gait and sit_to_stand are made of them.
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

#include "motion/joint_sequence.hpp"

namespace t2imu {

using BoneLengths = std::array<double, 22>;  // m, each joint's distance to its SMPL-22 parent; 0 for the pelvis

struct LegJoints {
    int hip, knee, ankle, toe;
};
extern const std::array<LegJoints, 2> kLegs;  // left, right (the Foot order of foot_contacts.hpp)

BoneLengths bone_lengths(const JointSequence& m, int frame);

// Throws Error(`options`, `field`) unless lo <= value <= hi (NaN fails): the editing options' range checks.
void check_option_range(double value, double lo, double hi, const char* options, const char* field);
// Largest |length - lengths[j]| over every bone and frame (m).
double max_bone_length_error(const JointSequence& m, const BoneLengths& lengths);
// Sets every bone to its length along its current direction, from the pelvis outward (children move with
// their parents, so the pelvis stays and each bone's direction is kept).
void restore_bone_lengths(JointSequence& m, const BoneLengths& lengths);

// The motion played at `speed` times its pace (< 1 slower), same fps: each joint coordinate interpolated
// between source frames by a monotone cubic (no overshoot: a planted foot does not dip into the floor), then
// bone lengths restored to the source's first frame with the ankles kept where the interpolation put them
// (knees re-solved by IK). speed in [0.25, 4].
JointSequence retime(const JointSequence& m, double speed);

// Minimum-jerk blend 10x^3 - 15x^4 + 6x^5 of x clamped to [0, 1] (Flash & Hogan 1985, J Neurosci): 0 -> 0,
// 1 -> 1, zero velocity and acceleration at both ends, so joined pieces do not jolt a virtual IMU.
double min_jerk(double x);

// Horizontal unit direction of `v` (Y dropped); throws Error when `v` has no horizontal part.
Eigen::Vector3d horizontal_direction(const Eigen::Vector3d& v);

// The body's facing at one frame (horizontal unit): across the hips and shoulders, left to right, turned to the
// front. Throws Error when that line is vertical.
Eigen::Vector3d body_facing(const JointSequence& m, int frame);

// `m` turned about the vertical through `pivot` so that the body faces `facing` (horizontal unit) at `frame`, and
// moved horizontally so that the pivot stands at `to`; heights unchanged. How one clip is set to go on from where
// and the way another ends (jump_series, gait_splice).
JointSequence turned_to_face(const JointSequence& m, int frame, const Eigen::Vector3d& facing,
                             const Eigen::Vector3d& pivot, const Eigen::Vector3d& to);

// spine1 and everything above it (spine, neck, head, collars, arms): the trunk as it bends at the hips.
bool is_trunk_joint(int joint);
// knees, ankles and toes: what moves with the feet or is re-solved by IK.
bool is_leg_joint(int joint);

// Bends the trunk of one frame forward by `angle_rad` (negative: backward) about the pelvis joint, around the
// horizontal axis across the body that faces `forward` (horizontal unit vector).
void flex_trunk(JointSequence& m, int frame, const Eigen::Vector3d& forward, double angle_rad);

// A smooth curve at or above x everywhere: a running maximum over +-radius samples, then a Gaussian of
// sigma radius/2 truncated at the same radius, whose window never reaches past the maximum's.
std::vector<double> upper_envelope(const std::vector<double>& x, int radius);

// Lowers every joint but the legs' (the pelvis, hips and trunk together) by a smooth amount per frame so that
// no hip is farther from its ankle than reach_m[leg]: the pelvis drops where feet placed on a staircase or a
// chair's geometry would otherwise stretch a leg past what the source did. Returns the largest drop (m).
double lower_to_reach(JointSequence& m, const std::array<double, 2>& reach_m);

// Per leg, the farthest the source's hip gets from its ankle (m), capped at 0.999 of thigh + shank (a knee
// fully straight has no side to bend to): what lower_to_reach should keep a derived motion's legs within.
std::array<double, 2> reach_limits(const JointSequence& source, const BoneLengths& lengths);

// Places both knees of every frame of `m` by two-bone IK from its hips to its ankles with the thigh and shank
// lengths of `lengths`, bending toward the knee of `source` (same frame count) carried along with the hip and
// pushed `forward` (horizontal unit) by kKneeHintPush, so a nearly straight source knee still bends forward and
// a knee raised high (seated, on a step) bends forward and up, the side the source's does not say. An ankle
// out of reach moves to the end of the stretched leg, its toe with it. Returns whether every ankle was reached.
constexpr double kKneeHintPush = 0.5;  // m
bool place_knees(JointSequence& m, const JointSequence& source, const Eigen::Vector3d& forward,
                 const BoneLengths& lengths);
// The same with a facing per frame (`forward` holds one horizontal unit per frame): for motions that turn.
bool place_knees(JointSequence& m, const JointSequence& source, const std::vector<Eigen::Vector3d>& forward,
                 const BoneLengths& lengths);

// Knee flexion of one leg at one frame (rad): the angle between thigh and shank, 0 when straight.
double knee_flexion_rad(const JointSequence& m, int frame, int leg);

}  // namespace t2imu
