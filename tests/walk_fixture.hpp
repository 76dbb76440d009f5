// A level walk whose geometry is known exactly, for the tests of stance detection, stair gait and the ground
// a motion stands on.
#pragma once
#include "motion/joint_sequence.hpp"
#include "motion/skeleton.hpp"

namespace t2imu::test {

constexpr double kWalkPelvisHeight = 0.82, kAnkleHeight = 0.08, kToeHeight = 0.02;  // m, in stance

// A level walk on HumanML3D's target skeleton along +Z at 1 m/s, one stride (two steps) a second: each foot
// stands still for 60% of its cycle and swings 1 m forward in the other 40% (minimum-jerk, 6 cm arc); the left
// foot lands at cycle phase 0, the right at 0.5. Upper body in the rest pose; knees by IK, bending forward.
JointSequence procedural_walk(double seconds, double fps = smpl22::kFps);

}  // namespace t2imu::test
