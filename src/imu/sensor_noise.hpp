// An optional, seeded error model of a MEMS IMU, applied to ideal signals (off by default).
//
// Per recording, in this order (a real sensor's signal chain): the true vector is multiplied by
// (I + scale) (I + misalignment) (per-axis scale errors, small cross-axis coupling), a bias is added (a constant
// drawn once plus a random walk), white noise is added, the result is clipped to the range and rounded to
// the resolution (LSB). Noise densities are in the datasheet units' SI equivalents: m/s^2/sqrt(Hz) and
// rad/s/sqrt(Hz); at sample rate fs the white noise has standard deviation density * sqrt(fs) (the bandwidth of
// an unfiltered output is fs/2 and the density is one-sided).
//
// Presets:
//   smartphone  a consumer 6-axis IMU as in the phones of RealWorld (datasheet-typical values of the
//               BMI160/LSM6DS3 class): acc 180 ug/sqrt(Hz), gyro 0.007 deg/s/sqrt(Hz), acc bias sd 40 mg, gyro
//               bias sd 1 deg/s, scale sd 0.01, misalignment sd 0.5 deg, +-8 g, +-2000 deg/s, 16 bit.
//   DATASET     each data set's device, in its profile (dataset_profile.cpp): realworld the smartphone,
//               sisfall's ADXL345/ITG-3200 board, umafall's SensorTag, hugadb's chip at +-2 g.
// `smartphone,acc_range_g=16,seed=3` overrides single fields (the realism model's sensor key, --realism
// none+sensor=MODEL).
#pragma once
#include <cstdint>
#include <string>

#include "imu/imu_synthesis.hpp"

namespace t2imu {

struct SensorNoiseModel {
    std::string name = "none";
    double acc_noise_density = 0, gyr_noise_density = 0;  // m/s^2/sqrt(Hz), rad/s/sqrt(Hz)
    double acc_bias_sd = 0, gyr_bias_sd = 0;              // m/s^2, rad/s (constant per recording)
    double acc_bias_walk = 0, gyr_bias_walk = 0;          // m/s^3/sqrt(Hz), rad/s^2/sqrt(Hz)
    double scale_sd = 0, misalignment_sd_rad = 0;
    double acc_range = 0, gyr_range = 0;  // +- full scale, m/s^2 and rad/s; 0 = unlimited
    int bits = 0;                         // resolution over the full range; 0 = none

    bool enabled() const { return name != "none"; }
};

// The consumer 6-axis chip of the smartphone class (BMI160 / LSM6DS3 datasheet-typical values), named "smartphone".
SensorNoiseModel smartphone_sensor();

// "none", "smartphone", a data set's device (dataset_profile.hpp), or one of these followed by ,key=value overrides
// (keys as the fields, with acc_range_g and gyr_range_dps in g and deg/s). `option` names the text's origin in
// errors: "--sensor", or a realism model's key ("r.toml: sensor").
SensorNoiseModel parse_noise_model(const std::string& text, const std::string& option = "sensor");
// How many times parse_noise_model has run in this process: tests check that a job parses its spelling once.
int64_t noise_model_parse_count();

// Applies the model in place. Deterministic in `seed`.
void apply_sensor_noise(const SensorNoiseModel& model, uint64_t seed, ImuSignals* signals);

}  // namespace t2imu
