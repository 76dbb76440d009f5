#include "analysis/static_segments.hpp"

#include <cmath>

#include "analysis/signal_statistics.hpp"
#include "core/error.hpp"

namespace t2imu {

namespace {

constexpr double kStandardGravity = 9.80665;  // m/s^2
const char* const kAxes[3] = {"x", "y", "z"};

// Channel c (0-5) of samples [from, from + n).
std::vector<double> channel(const ImuRecording& r, int c, size_t from, size_t n) {
    std::vector<double> out(n);
    for (size_t k = 0; k < n; ++k) out[k] = r.samples[from + k][static_cast<size_t>(c)];
    return out;
}

std::vector<double> magnitude(const ImuRecording& r, size_t from, size_t n) {
    std::vector<double> out(n);
    for (size_t k = 0; k < n; ++k) {
        const auto& s = r.samples[from + k];
        out[k] = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    }
    return out;
}

}  // namespace

nlohmann::json quietest_window_statistics(const ImuRecording& r, double window_s) {
    const size_t n = static_cast<size_t>(std::llround(window_s * r.rate_hz));
    if (n < 2 || r.samples.size() < n)
        throw Error(r.path, "samples",
                    "at least one " + std::to_string(window_s) + " s window (" + std::to_string(n) + " samples)",
                    std::to_string(r.samples.size()));
    size_t best = 0;
    double best_sd = INFINITY;
    for (size_t from = 0; from + n <= r.samples.size(); from += n)
        if (const double sd = standard_deviation(magnitude(r, from, n)); sd < best_sd) best_sd = sd, best = from;
    nlohmann::json j;
    double mean_acc[3];
    for (int a = 0; a < 3; ++a) {
        const std::vector<double> acc = channel(r, a, best, n), gyr = channel(r, 3 + a, best, n);
        j[std::string("acc_sd_") + kAxes[a]] = standard_deviation(acc);
        j[std::string("gyr_sd_") + kAxes[a]] = standard_deviation(gyr);
        j[std::string("gyr_mean_") + kAxes[a]] = mean_of(gyr);
        mean_acc[a] = mean_of(acc);
    }
    j["acc_norm_error"] =
        std::sqrt(mean_acc[0] * mean_acc[0] + mean_acc[1] * mean_acc[1] + mean_acc[2] * mean_acc[2]) - kStandardGravity;
    j["window_mag_sd"] = best_sd;
    j["window_start_s"] = static_cast<double>(best) / r.rate_hz;
    return j;
}

void StaticNoiseOptions::validate() const {
    if (!(window_s >= 0.5 && window_s <= 60))
        throw Error("--window", "window", "0.5 to 60 s", std::to_string(window_s));
}

nlohmann::json static_segment_noise(const std::vector<ImuRecording>& recordings, const StaticNoiseOptions& options,
                                    const SensorNoiseModel& sensor) {
    options.validate();
    const std::string& position = options.position;
    if (!position.empty()) check_position_held(recordings, position, "--position");
    const double window_s = options.window_s;
    nlohmann::json per = nlohmann::json::array();
    std::vector<double> rates;
    for (const ImuRecording& r : recordings) {
        if (!position.empty() && r.position != position) continue;
        if (r.samples.size() < static_cast<size_t>(std::llround(window_s * r.rate_hz))) continue;
        nlohmann::json j = quietest_window_statistics(r, window_s);
        j["path"] = r.path;
        j["activity"] = r.activity;
        per.push_back(j);
        rates.push_back(r.rate_hz);
    }
    if (per.empty())
        throw Error("static segments", "recordings",
                    "at least one recording of a whole window" + (position.empty() ? "" : " at " + position));
    const auto column = [&](const std::string& key) {
        std::vector<double> v;
        for (const auto& j : per) v.push_back(j[key].get<double>());
        return v;
    };
    nlohmann::json measured;
    for (const char* axis : kAxes) {
        measured[std::string("acc_sd_") + axis] = median_of(column(std::string("acc_sd_") + axis));
        measured[std::string("gyr_sd_") + axis] = median_of(column(std::string("gyr_sd_") + axis));
        measured[std::string("gyr_offset_sd_") + axis] = standard_deviation(column(std::string("gyr_mean_") + axis));
    }
    std::vector<double> norm_error = column("acc_norm_error");
    for (double& e : norm_error) e = std::fabs(e);
    measured["acc_norm_error_abs"] = median_of(norm_error);
    measured["window_mag_sd"] = median_of(column("window_mag_sd"));
    const double rate = median_of(rates);
    nlohmann::json out = {{"recordings", per.size()},
                          {"rate_hz", rate},
                          {"window_s", window_s},
                          {"measured", measured},
                          {"per_recording", per}};
    if (sensor.enabled())
        out["sensor_model"] = {{"model", sensor.name},
                               {"acc_sd", sensor.acc_noise_density * std::sqrt(rate / 2)},
                               {"gyr_sd", sensor.gyr_noise_density * std::sqrt(rate / 2)},
                               {"gyr_offset_sd", sensor.gyr_bias_sd},
                               {"acc_offset_sd", sensor.acc_bias_sd}};
    return out;
}

}  // namespace t2imu
