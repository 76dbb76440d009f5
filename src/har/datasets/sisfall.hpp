// SisFall (Sucerquia et al. 2017) release files -> the common IMU layout.
//
// `<activity code>_<subject>_<trial>.txt` (e.g. D05_SA01_R01.txt): one line per sample at 200 Hz, nine
// comma-separated raw integers ending in ';': ADXL345 acc x,y,z (13 bit, +-16 g: raw x 32/8192 g), ITG3200
// gyro x,y,z (16 bit, +-2000 deg/s: raw x 4000/65536 deg/s, the Readme's formula) and the MMA8451Q acc (not
// used). One device at the waist. Resampled to 50 Hz by resample_poly (1:4, Kaiser FIR, line padding).
// Activity codes kept: D01-D02 walking, D03-D04 jogging, D05-D06 stairs_up_down, D07, D09 sit_down_stand_up,
// D14 lying, D19 jump_reach; other codes (and the falls) are not imported.
#pragma once
#include <string>
#include <vector>

#include "imu/imu_dataset.hpp"

namespace t2imu {

std::vector<ImuRecording> read_sisfall_file(const std::string& path);  // empty for a code not kept
std::vector<ImuRecording> import_sisfall(const std::string& dir, std::vector<std::string>* skipped);

}  // namespace t2imu
