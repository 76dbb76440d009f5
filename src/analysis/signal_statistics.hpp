// Level and texture statistics of IMU recordings (the accelerometer; the gyroscope's sway and yaw), per
// activity, real beside synthetic: what a realism model is calibrated on and judged by (the two-sample test
// says *that* two sets differ, these say how).
//
// Per recording, after resampling to `rate_hz` (har/windowing.hpp's resample_channel, as HAR sees the data),
// acceleration in the sensor frame (m/s^2, gravity included):
//   mean_x/y/z        the mean: gravity's direction in the sensor frame while the activity goes on (m/s^2)
//   gravity_tilt_deg  angle between the mean vector and the sensor axis nearest to it (degrees): a mounting
//                     tilt, whatever the data set's axis convention
//   sd_x/y/z, mag_sd  standard deviations of each axis and of the magnitude |a| (m/s^2)
//   mag_p05/p50/p95   percentiles of |a| (m/s^2)
//   mag_rise/dip      the highest and lowest mean of |a| over 0.2 s, above and below mag_p50 (m/s^2): the swing of
//                     a transition (sitting down, standing up), whose pace sets it (~1 / duration^2)
//   dom_x/y/z_hz      frequency of the highest periodogram peak of each mean-removed axis in 0.3 Hz .. rate/2
//                     (zero-padded to >= 8 x the length); walking's stride (lateral sway) or step frequency
//   jerk_rms          root mean square of d|a|/dt by first differences (m/s^3)
//   hf_share          share of the mean-removed acceleration power (all axes) above 3 Hz
//   hf_sd_x/y/z       standard deviation of each axis's part above 3 Hz (m/s^2): sd x sqrt(the axis's share)
//   gyr_sway_sd_x/y/z standard deviation of each gyroscope axis's part in 0.5-3 Hz (rad/s): the turning of
//                     walking's stride and step, without turns and posture changes (trunk_sway.hpp's calibration);
//                     0 without a gyroscope
//   yaw_hz            frequency of the highest periodogram peak of the turning rate about the up direction (the
//                     gyroscope projected on the mean's direction): walking's stride frequency; 0 without a gyroscope
//   grav_x/y/z_re/im  at yaw_hz, each axis's gravity part over the rest (complex ratio G / K): G is what the
//                     sensor's turning (the gyroscope) does to gravity's projection on the axis, K = X - G its
//                     kinematic part. Walking's lateral axis: G from the roll; a ratio near -1 cancels the sway,
//                     near +1 adds to it, imaginary is in quadrature. 0 without a gyroscope
// Per activity (the evaluation class, class_map.hpp), the median over recordings, their count, and for two
// sets the ratio synthetic / real of every median and each set's spread over recordings (interquartile range
// / 1.349, a normal distribution's sd). Recordings shorter than 2 s are skipped.
#pragma once
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "imu/imu_dataset.hpp"

namespace t2imu {

// The mean and the median (halfway between the middle two for an even count) of x; 0 when x is empty.
double mean_of(const std::vector<double>& x);
double median_of(std::vector<double> x);
// The population standard deviation of x (divides by n; 0 for fewer than 2 values).
double standard_deviation(const std::vector<double>& x);
// The frequency (Hz) of the highest periodogram peak of x's mean-removed values at or above min_hz, zero-padded to
// a power of two >= 8 x the length (so peaks fall between the plain bins too); 0 for fewer than 2 values.
double dominant_frequency_hz(const std::vector<double>& x, double rate_hz, double min_hz);

// Statistic names in the order above.
const std::vector<std::string>& signal_statistic_names();

// One recording's statistics (names as above); throws Error for a recording under 2 s at rate_hz.
std::map<std::string, double> recording_signal_statistics(const ImuRecording& recording, double rate_hz);

struct SignalStatisticsOptions {
    std::string position;   // only recordings at this position; "" = every position
    double rate_hz = 20;    // resampled to this rate first (HAR's)
    void validate() const;  // throws Error naming --rate (8 to 1000 Hz)
};

// {activity: {"recordings": n, stat: median, ...}} over the recordings at the options' position.
nlohmann::json activity_signal_statistics(const std::vector<ImuRecording>& recordings,
                                          const SignalStatisticsOptions& options);

// One statistic's medians over recordings, real beside synthetic, and each set's spread over recordings.
struct StatisticComparison {
    double real = 0, synthetic = 0;
    double ratio = 0;  // synthetic / real; NaN where the real median is 0
    double real_spread = 0, synthetic_spread = 0;
};

struct ActivityComparison {
    int64_t real_recordings = 0, synthetic_recordings = 0;
    std::map<std::string, StatisticComparison> statistics;  // by signal_statistic_names()
};

// A signal-statistics comparison (`t2imu analysis signal-stats --synthetic`, an experiment's signal-stats/), by
// activity; its one schema, written and read here.
using SignalStatisticsComparison = std::map<std::string, ActivityComparison>;

// The activities both sets hold (after coarsening stairs as class_map.hpp does).
SignalStatisticsComparison compare_signal_statistics(const std::vector<ImuRecording>& real,
                                                     const std::vector<ImuRecording>& synthetic,
                                                     const SignalStatisticsOptions& options);
// {activity: {stat: {"real", "synthetic", "ratio", "real_spread", "synthetic_spread"}, "recordings": {"real",
// "synthetic"}}}
nlohmann::json signal_statistics_comparison_json(const SignalStatisticsComparison& comparison);
// Error naming `path` and the dotted key ("walking.mag_sd.ratio") when a field is missing or mistyped.
SignalStatisticsComparison parse_signal_statistics_comparison(const nlohmann::json& doc, const std::string& path);
SignalStatisticsComparison read_signal_statistics_comparison(const std::string& path);

}  // namespace t2imu
