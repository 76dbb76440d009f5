// Lying and turning onto the side and back, derived from a lying clip (SMPL-22 joints, metres, Y up, floor at
// y = 0): the whole body turns about its long axis, stays on its side a while and turns back. HAR data sets'
// "lying" holds such turns (SisFall's D14: on the back, onto the side, back again, in 12 s), open capture holds
// none, and a body lying still gives a waist sensor a level no real lying recording has (|a| sd 0.02 against
// SisFall's 0.86 m/s²).
//
// The turn is rigid: every joint of each frame turns by the same angle about the horizontal line along the trunk
// (pelvis to neck at frame 0) through the trunk's middle, so the source's own motion (breathing) plays on and
// the bones keep their lengths; the arms and legs turn with the trunk rather than being rearranged as a person
// does (a wrist sensor sees an arm carried round). The body is then raised by the least smooth amount that keeps
// every joint at or above the lowest height the source's joints had at frame 0 (the floor contact): the side
// lies higher than the back, as a hip's half width lies higher than the sacrum.
//
// Timeline: before_s lying as the source lies, turn_s turning (minimum jerk, as every edit of motion_edit.hpp),
// on_side_s on the side, back_s turning back, after_s lying again. The dataset builder draws the durations
// (derived_clips.hpp); docs/realism.md on lying turns measures the level they give against real lying
// recordings.
#pragma once
#include "motion/joint_sequence.hpp"

namespace t2imu {

struct LyingTurnOptions {
    double before_s = 1.5;   // [0, 10]
    double turn_s = 1.5;     // [0.8, 4]
    double on_side_s = 2.0;  // [0, 20]
    double back_s = 1.5;     // [0.8, 4]
    double after_s = 1.5;    // [0, 10]
    double angle_rad = 1.4;  // the turn about the head-ward long axis, right-handed; 0.5 <= |angle_rad| <= 1.7
};

// Throws Error naming the field when an option is outside its range.
void validate(const LyingTurnOptions& o);

// Frames the derived clip has (and the source must have at least): the timeline at fps, plus one.
int lying_turn_frames(const LyingTurnOptions& o, double fps);

// Refuses (Error) a source that is not 22 joints, is shorter than lying_turn_frames or is not lying at frame 0
// (lying_still.hpp's is_lying).
JointSequence lying_turn(const JointSequence& lying, const LyingTurnOptions& o);

}  // namespace t2imu
