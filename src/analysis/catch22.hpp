// catch22 / catch24: the 22 CAnonical Time-series CHaracteristics of Lubba et al. (2019, Data Min Knowl Disc
// 33:1821-1852), plus the mean and standard deviation (catch24). The evaluation of the paper compares real and
// synthetic IMU windows with these features. Each feature is written from its published definition (the
// paper's supplementary and hctsa's documentation of the original operations) and checked against the outputs
// of the reference implementation.
#pragma once
#include <string>
#include <vector>

namespace t2imu {

// The shortest series catch22 accepts: shorter ones leave the lag-based features without any lag to use.
constexpr std::size_t kCatch22MinLength = 10;

// Feature names in the canonical (featureList) order: the 22 catch22 features, then DN_Mean, DN_Spread_Std.
const std::vector<std::string>& catch24_names();
// The short names of the same features, same order ("mode_5", "acf_timescale", ...).
const std::vector<std::string>& catch24_short_names();

// The features of `series` in the canonical order: 22 values, or 24 with `catch24`. The catch22 features are
// computed on the z-scored series, DN_Mean and DN_Spread_Std on the series as given. Throws t2imu::Error,
// naming `source`, for a series shorter than kCatch22MinLength, one with NaN or infinite values, or a
// constant one (it cannot be z-scored).
std::vector<double> catch22(const std::vector<double>& series, bool catch24 = false,
                            const std::string& source = "series");

// The order in which the reference C command-line program prints the features: element i is the canonical
// index of its i-th output line (22 or 24 entries).
std::vector<std::size_t> catch22_reference_output_order(bool catch24);

// A series read as the reference program does: whitespace-separated decimal numbers ("nan" and "inf" parse,
// so that the check in catch22() can refuse them with a clear message).
std::vector<double> read_catch22_series(const std::string& path);

}  // namespace t2imu
