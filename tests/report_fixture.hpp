// A small synthesis folder as `t2imu synth` writes it, and a small real IMU data set, for the report's tests.
//
// Synthesis folder (write_synth_fixture): three jobs
//   j00000 walking, kept on its first draw, activity check shows walking (agreement 0.83, passed)
//   j00001 running, kept on its second draw (the first skated), activity check shows walking (0.40, below)
//   j00002 walking, dropped (no motion files)
// each kept job with motions/<job>_joints.npy (a 40-frame walk cycle of the SMPL-22 rest skeleton, 20 fps),
// motions/<job>.bvh, and recordings (64 Hz, 4 s) whose |acc| is 9.81 + A sin(2 pi f t):
//   j00000: waist A = 1 and A = 3 at 2 Hz, chest A = 1 at 2 Hz   (waist: |acc| sd 0.71 and 2.12, median 1.41)
//   j00001: waist A = 4 at 3 Hz                                  (|acc| sd 2.83)
// Real data set (write_real_fixture): walking at the waist A = 2 at 1.75 Hz (sd 1.41) and at the chest, and
// applauding at the waist (an activity the synthetic data lacks).
#pragma once
#include <string>

#include "imu/imu_dataset.hpp"
#include "motion/joint_sequence.hpp"

namespace t2imu::test {

// A walk on the spot of the SMPL-22 rest skeleton (smpl22::kTargetOffsets): legs and arms swing about X at
// `stride_hz`, the pelvis advances along +Z at 1 m/s, the lowest joint touches the floor (y = 0).
JointSequence fixture_walk(int frames, double stride_hz = 1.0);

// A recording of `seconds` at `rate_hz` with acc = (0, 9.81 + amplitude sin(2 pi hz t), 0) m/s^2, gyro zero.
ImuRecording sine_recording(const std::string& path, const std::string& activity, const std::string& position,
                            double amplitude, double hz, double rate_hz = 64, double seconds = 4);

void write_synth_fixture(const std::string& dir);
void write_real_fixture(const std::string& dir);

}  // namespace t2imu::test
