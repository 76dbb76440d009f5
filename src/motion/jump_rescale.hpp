// Jumps of another height, derived from a captured jump (SMPL-22 joints, metres, Y up, floor at y = 0). Open
// capture holds 4 minutes of jumping (CMU, HDM05's hopBothLegs); jumps vary in height from person to person and
// try to try, and this edit gives a captured jump a lower or higher one without breaking its physics.
//
// The edit plays the jump k times slower (motion_edit's retime) and stretches the body's vertical excursion from
// its standing height by k^2. Under that pair every vertical acceleration of the body is kept:
// y_new(t) = k^2 y(t / k) has y_new''(t) = y''(t / k). So a flight stays ballistic (-g), the push-off and the
// landing take the same accelerations (forces per kilogram) for k times as long, and the body rises k^2 as
// high, k times as long in the air, as projectile motion demands (apex h = g T^2 / 8 for a flight of T s).
// Horizontal travel is kept, at 1/k of the speed. A foot in stance (foot_contacts.hpp) stays where it is; a foot
// in the air rises with the body; knees are re-solved by two-bone IK bending the way the source's do (an ankle
// out of the stretched leg's reach rises to it: the heel leaves the floor a little earlier).
//
// Standing height: the median pelvis height over the frames where both feet are in stance. Which constant is
// taken does not change any acceleration, only how deep a crouch or how high a landing pose is scaled.
#pragma once
#include "motion/joint_sequence.hpp"

namespace t2imu {

struct JumpRescaleOptions {
    double time_scale = 1.1;  // k, [0.8, 1.25]: flight k times as long, k^2 times as high
};

// Throws Error naming the field when an option is outside its range.
void validate(const JumpRescaleOptions& o);

// The jump with every vertical excursion of the body scaled by k^2 and time by k (header comment). Refuses
// (Error) a source that is not 22 joints, shorter than 0.5 s, or has no frame with both feet in stance.
JointSequence rescale_jump(const JointSequence& jump, const JumpRescaleOptions& o);

}  // namespace t2imu
