// Physical plausibility of a motion (joint positions, metres, Y up, floor at y = 0 as HumanML3D's
// representation puts it): the scores a quality filter uses to drop or regenerate a generated motion.
// Heights are taken above the ground the motion stands on (support_ground.hpp: the floor, and the treads,
// steps or kerbs its grounded footholds show), so a climb is not read as hovering:
//
//   foot_skate_m_s      mean horizontal speed (m/s) of the feet (ankle and toe joints) over the frames where
//                       that joint is within kContactHeight of the ground: a planted foot should not slide
//   penetration_m       deepest any joint goes below the ground (m)
//   hover_m             median over frames of the lowest joint's height above the ground under it (m): a body
//                       floating above the floor or the treads
//   max_speed_m_s       fastest joint, first difference (m/s)
//   max_acc_m_s2        largest joint acceleration, second difference (m/s^2): jitter and teleports
//   pelvis_acc_m_s2     largest pelvis (root joint) acceleration, second difference (m/s^2): a body that
//                       teleports, which a hip or waist sensor turns into a spike of several g. Hands and
//                       feet move fast in captured motion, so max_acc_m_s2 must allow 350 m/s^2 and misses
//                       a draw whose pelvis drops 0.52 m in one frame and comes back (340 m/s^2, lying down)
//
// The default thresholds sit at the 99.5th percentile of the captured motions of our dataset (2,524 clips of
// the shared mocap with mirrors, `t2imu motion quality cache/dataset/new_joints`), rounded up: foot skating
// 1.28 m/s, hover 0.25 m, joint speed 13.2 m/s, joint acceleration 346 m/s^2, pelvis acceleration 57 m/s^2
// (medians 0.20, 0.014, 4.9, 56, 10).
// Captured clips never go below the floor (HumanML3D puts the floor at their lowest joint); 5 cm is allowed.
// So a motion that fails one is less plausible than 199 in 200 captured motions.
// One set for every activity, not one per activity: per activity the 99.5th percentile of foot skating is
// 1.16 m/s for running (752 clips, mirrors counted), 1.68 walking (672), 2.71 dancing (312), 0.67 jumping
// (138), so a running threshold would be stricter, not looser: generated jogging that skates 1.5 m/s skates
// more than captured running does.
#pragma once
#include <Eigen/Core>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "motion/joint_sequence.hpp"

namespace t2imu {

struct MotionQuality {
    double foot_skate_m_s = 0, penetration_m = 0, hover_m = 0, max_speed_m_s = 0, max_acc_m_s2 = 0, pelvis_acc_m_s2 = 0;
};

struct MotionQualityThresholds {
    double foot_skate_m_s, penetration_m, hover_m, max_speed_m_s, max_acc_m_s2, pelvis_acc_m_s2;
};

constexpr double kContactHeight = 0.05;  // m above the floor

// The six scores in one order, for tables and records: names as the fields above, with their units.
constexpr size_t kNumQualityScores = 6;
extern const std::array<const char*, kNumQualityScores> kQualityScoreNames;  // "foot_skate_m_s", ...
std::array<double, kNumQualityScores> quality_scores(const MotionQuality& q);
std::array<double, kNumQualityScores> quality_limits(const MotionQualityThresholds& t);

MotionQualityThresholds default_quality_thresholds();

// SMPL-22 joints, at least 3 frames; the ground is the motion's SupportGround (support_ground.hpp). The one
// scoring path of generated motion (synth), derived clips (the data builder) and `t2imu motion quality`.
MotionQuality score_motion(const JointSequence& joints);

// The ground's height (m) under a point (its y ignored) at a frame, for motion over uneven ground: a staircase.
using GroundHeight = std::function<double(const Eigen::Vector3d&, int frame)>;
// As score_motion, with every height (foot contact, penetration, hover) taken above the ground under the joint
// instead of above y = 0; the speed and acceleration scores do not depend on the ground.
MotionQuality score_motion_on_ground(const JointSequence& joints, const GroundHeight& ground);

// Shifts the whole motion vertically so its lowest joint over all frames is at y = 0: where HumanML3D's processing
// puts the floor of a captured clip. A generated motion's floor can sit 0.2-0.4 m too high (lying motions sink
// through it); one constant shift changes no velocity, acceleration or orientation, so no virtual IMU sample, and
// what stays of a sinking that varies over the clip shows as hover. Returns the shift (m, up positive).
double place_on_floor(JointSequence& joints);

// Names of the scores over their threshold, empty when the motion passes.
std::vector<std::string> quality_failures(const MotionQuality& q, const MotionQualityThresholds& t);

// How far past its worst threshold a motion is (max of score/threshold; < 1 passes): ranks failed attempts.
double quality_badness(const MotionQuality& q, const MotionQualityThresholds& t);

}  // namespace t2imu
