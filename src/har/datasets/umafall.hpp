// UMAFall (Casilari et al. 2017) release files -> the common IMU layout.
//
// `UMAFall_Subject_<NN>_<ADL|Fall>_<Movement>_<trial>_<date>.csv`: `%` header lines (among them the
// "MAC; Sensor_ID; Position; Device" table), then rows `TimeStamp;Sample No;X;Y;Z;Sensor Type;Sensor ID` with
// type 0 = accelerometer (g), 1 = gyroscope (deg/s), 2 = magnetometer. The four SensorTags (ankle, waist,
// chest, wrist; MPU-9250) stream at a nominal 20 Hz over BLE; one accelerometer and one gyroscope row with the
// same Sample No come from one notification, so they are paired by it (samples without both are dropped).
// The logged timestamps are phone arrival times with BLE jitter, so t = k / 20 s. acc x 9.80665 -> m/s^2, gyro
// x pi/180 -> rad/s. `gyro_flag` is "clipped" when more than 0.005 of the samples reach the +-256 deg/s limit. The
// phone in the pocket (no gyroscope) and the falls are not imported.
#pragma once
#include <string>
#include <vector>

#include "imu/imu_dataset.hpp"

namespace t2imu {

std::vector<ImuRecording> read_umafall_file(const std::string& path);  // empty for a fall trial
// Every UMAFall_*.csv under dir (recursively); files that cannot be read (e.g. subject 13's numbers with
// thousands separators) are skipped and named in `skipped` with the reason.
std::vector<ImuRecording> import_umafall(const std::string& dir, std::vector<std::string>* skipped);

}  // namespace t2imu
