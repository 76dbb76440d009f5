// Twelve posture and movement statistics of a motion (SMPL-22 joints, metres, Y up, floor at y = 0 as in
// HumanML3D), chosen to tell the evaluation's activities apart by what defines them: how high the pelvis is
// and whether the trunk and thighs are upright (standing, sitting, lying), how fast the body travels and
// bounces (walking, running), whether both feet leave the ground (jumping), whether the feet climb (stairs),
// and how much the limbs move (dancing). All are left-right symmetric, so a mirrored motion has the same ones.
//
//   pelvis_height_m            mean pelvis height above the floor
//   pelvis_height_sd_m         its standard deviation
//   head_above_pelvis_m        mean head height minus pelvis height (about 0.6 upright, about 0 lying)
//   trunk_tilt_rad             mean angle of pelvis -> neck from vertical
//   thigh_tilt_rad             mean angle of knee -> hip from vertical, both legs (about 0 standing, pi/2 seated)
//   knee_flexion_rad           mean knee bend, both legs (0 = straight)
//   root_speed_m_s             mean horizontal pelvis speed
//   root_vertical_speed_sd_m_s standard deviation of the pelvis's vertical velocity (bounce)
//   climb_rate_m_s             slope of a least-squares line through the lowest foot joint's height over time:
//                              positive up stairs, negative down (stairs_up and stairs_down are classes)
//   foot_speed_m_s             mean ankle speed
//   wrist_speed_m_s            mean wrist speed relative to the pelvis
//   airborne_fraction          share of frames whose lowest foot joint is more than kAirborneHeight above both
//                              the lowest it gets in the second before and in the second after (so the
//                              step a climbing foot stands on is its floor: stairs are not flight)
#pragma once
#include <array>
#include <vector>

#include "motion/joint_sequence.hpp"

namespace t2imu {

constexpr size_t kNumMotionDescriptors = 12;
constexpr double kAirborneHeight = 0.05;  // m
extern const std::array<const char*, kNumMotionDescriptors> kMotionDescriptorNames;

using MotionDescriptors = std::array<double, kNumMotionDescriptors>;

// At least 3 frames of SMPL-22 joints; throws Error otherwise.
MotionDescriptors describe_motion(const JointSequence& joints);

// Per descriptor over a set of motions: mean and (population) standard deviation. Empty input gives zeros.
struct DescriptorMoments {
    MotionDescriptors mean{}, sd{};
};
DescriptorMoments descriptor_moments(const std::vector<MotionDescriptors>& set);

}  // namespace t2imu
