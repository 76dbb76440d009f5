// Foot landings found on a motion's joints: when each foot's ankle comes to rest after a swing. The realism
// model's landing transients (imu/heel_strike.hpp) restore what a 20 fps motion loses of each one.
//
// Landings: per foot, the first frame of a run of at least two frames in which the ankle moves slower than
// kLandingSpeed (3-D, central difference), after a frame at which it moved faster: level walking, running and
// stairs alike (no floor height is assumed). The transients' size (heel_strike.hpp) is gain x the segment's
// transmissibility, the same for every landing: the size of a landing is not read from the motion, because a
// 20 fps foot path does not carry it.
// Scaled by the ankle's landing speed, derived stair descents landed 3-4 times harder than level walks (waist
// jerk 90-100 against 40-45 m/s^3), against real SisFall stair trials that are gentler than their walks (40
// against 47 m/s^3, median per recording).
#pragma once
#include <vector>

#include "motion/joint_sequence.hpp"

namespace t2imu {

constexpr double kLandingSpeed = 1.0;  // m/s: a swinging foot moves at 2-6 m/s, a planted ankle rolls below this

struct Landing {
    double time_s;  // the moment of contact: half a frame before the first slow frame
};

// Every landing of either foot in a SMPL-22 motion, in time order.
std::vector<Landing> detect_landings(const JointSequence& motion);

}  // namespace t2imu
