// Sensor errors seen in real recordings: the quietest stretch of each recording (a person lying or standing
// still, a sensor put down) holds what the sensor adds to a still body: white noise, the gyroscope's zero-rate
// offset, the accelerometer's offset and scale error. This is what the sensor models (imu/sensor_noise.hpp) are
// checked against, beside their data sheets.
//
// Per recording, at its own rate: non-overlapping windows of `window_s`; the quietest is the window with the
// smallest standard deviation of the acceleration magnitude. Its statistics (sensor frame):
//   acc_sd_x/y/z    standard deviation of each accelerometer axis, m/s^2: white noise, plus body micro-motion
//                   (breathing, sway), so an upper bound on the sensor's noise
//   gyr_sd_x/y/z    the same for the gyroscope, rad/s
//   gyr_mean_x/y/z  the gyroscope's mean, rad/s: its zero-rate offset (a still body does not turn)
//   acc_norm_error  |mean acceleration| - g, m/s^2: offset and scale error together (a still body feels g)
//   window_mag_sd   the window's |a| standard deviation, m/s^2 (how still it was)
// Summary over recordings: the median of each sd (noise), the spread (sd over recordings) of each gyr_mean
// (offset sd across devices or power-ups) and the median |acc_norm_error|. With a sensor model, the same
// figures it predicts at the data's rate: white noise sd = density * sqrt(rate / 2) (the band up to Nyquist;
// a copy resampled with a low-pass filter keeps that band), offsets as its bias sd.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "imu/imu_dataset.hpp"
#include "imu/sensor_noise.hpp"

namespace t2imu {

// The quietest window's statistics (names above); throws Error for a recording shorter than one window.
nlohmann::json quietest_window_statistics(const ImuRecording& recording, double window_s);

struct StaticNoiseOptions {
    std::string position;   // only recordings at this position; "" = every position
    double window_s = 2;    // window length, s
    void validate() const;  // throws Error naming --window (0.5 to 60 s)
};

// {"recordings": n, "rate_hz": median rate, "measured": {...}, "per_recording": [...]} over the recordings at
// the options' position of at least one window; with `sensor` enabled, also "sensor_model": {...} (what it predicts).
nlohmann::json static_segment_noise(const std::vector<ImuRecording>& recordings, const StaticNoiseOptions& options,
                                    const SensorNoiseModel& sensor);

}  // namespace t2imu
