// A captured walk turned onto a curve: where open motion capture walks straight (the shared set's walking chunks
// turn less than 45 degrees, docs/attributes.md), a turn of a chosen size and side, so that "walks and turns
// left" has motions that do.
//
// The heading follows a minimum-jerk ramp from 0 to turn_rad between start_s and start_s + duration_s. Each
// frame's increment of heading is a rotation about the vertical through the planted foot (foot_contacts.hpp;
// in double support the one that landed last, the pelvis when neither is planted), applied on top of all
// earlier ones: a person turning while walking pivots on the stance foot, so that foot does not slide; the
// trailing foot of a double support turns with the body until it pushes off. SMPL-22
// joints, metres, Y up; positive angles turn left (counter-clockwise seen from above).
#pragma once
#include "motion/joint_sequence.hpp"

namespace t2imu {

struct WalkTurnOptions {
    double turn_rad = 1.5707963267948966;  // + left, |turn| at most pi
    double start_s = 1.0;                  // when the turn begins, >= 0
    double duration_s = 1.5;               // how long it takes, > 0; start + duration within the walk
};

// Throws Error naming the field when the options do not fit the walk (SMPL-22, at least 3 frames).
JointSequence turn_walk(const JointSequence& walk, const WalkTurnOptions& o);

}  // namespace t2imu
