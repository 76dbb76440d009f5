// A series of jumps made from single captured ones (SMPL-22 joints, metres, Y up, floor at y = 0). Open capture's
// jumps are mostly single: HDM05's hopBothLegs1hops clips last 0.6-0.7 s, under the 2 s (40 frames at 20 fps) that
// MDM's data rules (hml3d_dataset.hpp) keep, so of the 113 jumping-tagged clips of the mocap v5's training split
// (mirrors aside) 70 never reached a training batch (36 captured hops, 34 rescaled from them), while a HAR data set's
// "jumping" is jumping over and over.
//
// The series plays the jumps one after another. Each next jump is turned about the vertical through its first
// pelvis position and moved horizontally so that it starts where, and facing the way, the previous one ends (its
// heights are kept: each jump stands on the floor). Over `blend_s` seconds the end of one and the start of the next
// overlap and cross-fade linearly, both standing on both feet there (a captured single jump starts and ends in
// stance), and every bone is then set back to the first jump's length (a blend of two poses shortens bones a
// little). Flights, push-offs and landings are the captured ones.
#pragma once
#include <vector>

#include "motion/joint_sequence.hpp"

namespace t2imu {

struct JumpSeriesOptions {
    double blend_s = 0.1;  // cross-fade between consecutive jumps, [0.05, 0.3] s
};

// Throws Error naming the field when an option is outside its range.
void validate(const JumpSeriesOptions& o);

// The jumps, at least two, chained (header comment). Refuses (Error) jumps that are not SMPL-22 joints at one
// frame rate, or one shorter than three blend windows.
JointSequence chain_jumps(const std::vector<JointSequence>& jumps, const JumpSeriesOptions& o);

}  // namespace t2imu
