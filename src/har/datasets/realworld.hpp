// RealWorld HAR (Sztyler & Stuckenschmidt 2016) release -> the common IMU layout.
//
// Release layout: `proband<N>/data/<sensor>_<activity>_csv.zip` (sensor `acc` or `gyr`), each holding
// `<Sensor>_<activity>_<position>.csv` (`acc_...`, `Gyroscope_...`) with columns id,attr_time,attr_x,attr_y,attr_z
// (attr_time in ms, Android units: m/s^2 including gravity, rad/s). Long sessions are split into parts
// `acc_<activity>_<n>_<position>.csv`, and some archives hold those parts as nested zips. Files may be missing
// (then that position is left out).
// Every stream is sampled at about 50 Hz on its own clock; the positions are not synchronised with each other.
// Each session part is therefore put on one 50 Hz grid shared by all its positions, from the latest first
// sample to the earliest last sample of all its streams, and every stream is linearly interpolated onto it, so
// windows of different positions line up in time. Activities map to climbingdown -> stairs_down, climbingup ->
// stairs_up; the others keep their names. Positions have no side (the release does not give one).
#pragma once
#include <string>
#include <vector>

#include "imu/imu_dataset.hpp"

namespace t2imu {

constexpr double kRealWorldRateHz = 50.0;

// The recordings of one proband folder (`.../proband<N>`).
std::vector<ImuRecording> read_realworld_proband(const std::string& proband_dir, std::vector<std::string>* skipped);
// Every proband<N> folder under dir.
std::vector<ImuRecording> import_realworld(const std::string& dir, std::vector<std::string>* skipped);

}  // namespace t2imu
