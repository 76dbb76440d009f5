// Virtual IMU signals on disk: the project's per-position CSV and the RealWorld HAR release layout.
#pragma once
#include <string>

#include "imu/imu_synthesis.hpp"

namespace t2imu {

// `t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z` (s, m/s^2 with gravity, rad/s), the IMU dataset layout's recording
// file. Atomic.
void write_imu_csv(const std::string& path, const ImuSignals& s);

// RealWorld's release files in `dir`: acc_<activity>_<position>.csv and Gyroscope_<activity>_<position>.csv
// with `id,attr_time,attr_x,attr_y,attr_z` (id from 1, attr_time in ms from `start_ms`). Atomic.
void write_realworld_csv(const std::string& dir, const std::string& activity, const std::string& position,
                         const ImuSignals& s, long long start_ms = 0);

}  // namespace t2imu
