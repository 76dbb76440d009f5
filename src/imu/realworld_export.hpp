// Virtual IMU signals in the RealWorld HAR release layout (the paper's test set; har/datasets/realworld.hpp reads it),
// for users who feed synthetic data to tools written for RealWorld. The project's own layout is imu/imu_dataset.hpp.
#pragma once
#include <string>

#include "imu/imu_synthesis.hpp"

namespace t2imu {

// RealWorld's release files in `dir`: acc_<activity>_<position>.csv and Gyroscope_<activity>_<position>.csv
// with `id,attr_time,attr_x,attr_y,attr_z` (id from 1, attr_time in ms from `start_ms`). Atomic.
void write_realworld_csv(const std::string& dir, const std::string& activity, const std::string& position,
                         const ImuSignals& s, long long start_ms = 0);

}  // namespace t2imu
