// HuGaDB v1 (Chereshnev & Kertész-Farkas 2018) release files -> the common IMU layout.
//
// A file `HuGaDB_v1_<activity>_<subject>_<trial>.txt` has `#Activity`, `#ActivityID` and `#Date` lines, a
// header of 39 tab-separated columns and one row per sample: for the right foot, shin, thigh and the left foot,
// shin, thigh (RF, RS, RT, LF, LS, LT) acc x,y,z and gyro x,y,z as raw int16, then two EMG channels and the
// activity id. Units per the release README: acc +-2 g (raw x 2/32768 x 9.80665 m/s^2), gyro +-2000 deg/s
// (raw x 2000/32768 x pi/180 rad/s). v1 files have no timestamps: t = i / 58.82 s, the README's nominal rate.
// Runs of one activity id become segments `seg<k>`. Activity ids 1-12 map to walking, running, stairs_up,
// stairs_down, sitting, sitting_down, standing_up, standing, bicycling, elevator_up, elevator_down,
// sitting_in_car. Some gyroscopes are documented as amplified tenfold and clipped; the files do not say which,
// so `gyro_flag` is "unknown" (the shared compact copy carries the README's table).
#pragma once
#include <string>
#include <vector>

#include "imu/imu_dataset.hpp"

namespace t2imu {

constexpr double kHuGaDBRateHz = 58.82;

std::vector<ImuRecording> read_hugadb_file(const std::string& path);
std::vector<ImuRecording> import_hugadb(
    const std::string& dir);  // every HuGaDB_v1_*.txt under dir; stops at a bad file

}  // namespace t2imu
