// Lying still, derived from the end of a captured lie-down clip (SMPL-22 joints, metres, Y up, floor at y = 0):
// the final pose held, with quiet breathing as the only motion. Open capture has little lying and less lying
// still (HDM05's lieDownFloor clips end within seconds of reaching the floor), yet "lying" recordings of HAR
// data sets are mostly still: this fills that gap with what a body-worn IMU sees of a resting body.
//
// Breathing: the rib cage and everything it carries (spine3 and above: neck, head, collars, arms) turns rigidly
// about the spine2 joint around the body's left-right axis (across the hips), by chest_rad * (1 - cos(2 pi f t))
// / 2: inhaling from the end of an exhale, f = breaths_per_min / 60, in the direction that lifts the head:
// supine the chest and head rise, prone the back rises rather than the chest sinking into the floor, on the
// side they move forward or back. The hands stay where they rest (on the floor, on the belly), the elbows
// re-solved by two-bone IK from the moving shoulders; turning them with the chest would press the hands of
// arms lying beside the hips into the floor. Quiet breathing at rest runs at about 12-20 breaths/min in adults (the
// clinical normal range), and at tidal volume the chest wall moves millimetres, not centimetres; chest_rad 0.02
// moves the head about 8 mm and the spine3 joint about 1 mm on HumanML3D's skeleton.
#pragma once
#include "motion/joint_sequence.hpp"

namespace t2imu {

struct LyingOptions {
    double seconds = 10.0;          // length of the derived clip, [1, 120]
    double breaths_per_min = 14.0;  // [8, 25]
    double chest_rad = 0.02;        // peak rib-cage turn, [0, 0.05]
};

// Throws Error naming the field when an option is outside its range.
void validate(const LyingOptions& o);

// Whether frame f of s is lying: the pelvis below 0.4 m and the pelvis-to-neck line more than 45 deg from vertical.
bool is_lying(const JointSequence& s, int f);

// The source's last frame held for o.seconds at its fps, breathing. Refuses (Error) a source that is not
// 22 joints or does not end lying: pelvis above 0.4 m, or the pelvis-to-neck line within 45 deg of vertical.
JointSequence lying_still(const JointSequence& lie_down, const LyingOptions& o);

}  // namespace t2imu
