#include "analysis/signal_statistics.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <complex>
#include <set>

#include "core/error.hpp"
#include "core/json_file.hpp"
#include "core/signal/fft.hpp"
#include "har/class_map.hpp"
#include "har/windowing.hpp"
#include "imu/imu_synthesis.hpp"

namespace t2imu {

namespace {

constexpr double kMinSeconds = 2;
constexpr double kMinDominantHz = 0.3;
constexpr double kHighFrequencyHz = 3;
constexpr double kSwayLowHz = 0.5, kSwayHighHz = 3;  // gyr_sway_sd's band: stride and step, not turns or posture
constexpr double kSwingSeconds =
    0.2;  // mag_rise / mag_dip average |a| over this long: a movement's swing, not a step's spike

// Means of every run of `width` consecutive values (width <= x.size()).
std::vector<double> moving_mean(const std::vector<double>& x, size_t width) {
    std::vector<double> out;
    double sum = 0;
    for (size_t i = 0; i < x.size(); ++i) {
        sum += x[i];
        if (i >= width) sum -= x[i - width];
        if (i + 1 >= width) out.push_back(sum / static_cast<double>(width));
    }
    return out;
}

double percentile(std::vector<double> x, double p) {
    std::sort(x.begin(), x.end());
    const double pos = p * static_cast<double>(x.size() - 1);
    const size_t lo = static_cast<size_t>(std::floor(pos));
    const size_t hi = std::min(lo + 1, x.size() - 1);
    return x[lo] + (pos - static_cast<double>(lo)) * (x[hi] - x[lo]);
}

// Periodogram |X_k|^2 of the mean-removed series, zero-padded to a power of two >= 8 n; bin k is k rate / N Hz.
std::vector<double> periodogram(const std::vector<double>& x, size_t* length) {
    const double m = mean_of(x);
    const size_t n = next_power_of_two(8 * x.size());
    std::vector<std::complex<double>> data(n);
    for (size_t i = 0; i < x.size(); ++i) data[i] = x[i] - m;
    fft_in_place(data);
    std::vector<double> power(n / 2 + 1);
    for (size_t k = 0; k < power.size(); ++k) power[k] = std::norm(data[k]);
    *length = n;
    return power;
}

// The Fourier coefficient of x's mean-removed values at f Hz (a single-frequency DFT over the whole series).
std::complex<double> fourier_at(const std::vector<double>& x, double rate_hz, double f) {
    const double m = mean_of(x);
    std::complex<double> sum = 0;
    for (size_t i = 0; i < x.size(); ++i)
        sum += (x[i] - m) * std::polar(1.0, -2 * M_PI * f * static_cast<double>(i) / rate_hz);
    return sum * (2.0 / static_cast<double>(x.size()));
}

// Axis a's gravity part over the rest, at f Hz: the sensor's turning (gyroscope) moves the up direction u (the
// mean specific force's direction) as du/dt = u x omega in the sensor frame, so gravity contributes
// g (u x Omega(f))_a / (i 2 pi f) to the axis's Fourier coefficient X_a(f); the rest is the kinematic part.
std::complex<double> gravity_ratio(const std::vector<double> acc[3], const std::vector<double> gyr[3],
                                   const Eigen::Vector3d& up, int a, double rate_hz, double f) {
    if (f <= 0 || up.norm() == 0) return 0;
    std::complex<double> omega[3];
    for (int k = 0; k < 3; ++k) omega[k] = fourier_at(gyr[k], rate_hz, f);
    const Eigen::Vector3d u = up.normalized();
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    const std::complex<double> turned = u[b] * omega[c] - u[c] * omega[b];  // (u x Omega)_a
    const std::complex<double> gravity = kGravity * turned / std::complex<double>(0, 2 * M_PI * f);
    const std::complex<double> rest = fourier_at(acc[a], rate_hz, f) - gravity;
    return std::abs(rest) > 0 ? gravity / rest : 0.0;
}

}  // namespace

double mean_of(const std::vector<double>& x) {
    double s = 0;
    for (double v : x) s += v;
    return x.empty() ? 0 : s / static_cast<double>(x.size());
}

double median_of(std::vector<double> x) { return x.empty() ? 0 : percentile(std::move(x), 0.5); }

double standard_deviation(const std::vector<double>& x) {
    if (x.size() < 2) return 0;
    const double m = mean_of(x);
    double s = 0;
    for (double v : x) s += (v - m) * (v - m);
    return std::sqrt(s / static_cast<double>(x.size()));
}

namespace {

// The frequency of the highest bin at or above min_hz of a periodogram of `length` points at rate_hz.
double peak_frequency(const std::vector<double>& p, size_t length, double rate_hz, double min_hz) {
    size_t best = 0;
    for (size_t k = 1; k < p.size(); ++k) {
        const double f = static_cast<double>(k) * rate_hz / static_cast<double>(length);
        if (f >= min_hz && (best == 0 || p[k] > p[best])) best = k;
    }
    return static_cast<double>(best) * rate_hz / static_cast<double>(length);
}

// The standard deviation (same units as x) of x's part in [lo_hz, hi_hz): Parseval on the zero-padded
// periodogram, whose bins sum (DC excluded, the one-sided bins counted twice but Nyquist) to n x the variance.
double band_sd(const std::vector<double>& x, double rate_hz, double lo_hz, double hi_hz) {
    if (x.size() < 2) return 0;
    size_t length = 0;
    const std::vector<double> p = periodogram(x, &length);
    double band = 0;
    for (size_t k = 1; k < p.size(); ++k) {
        const double f = static_cast<double>(k) * rate_hz / static_cast<double>(length);
        if (f >= lo_hz && f < hi_hz) band += (k + 1 == p.size() ? 1 : 2) * p[k];
    }
    return std::sqrt(band / static_cast<double>(length) / static_cast<double>(x.size()));
}

}  // namespace

double dominant_frequency_hz(const std::vector<double>& x, double rate_hz, double min_hz) {
    if (x.size() < 2) return 0;
    size_t n = 0;
    const std::vector<double> p = periodogram(x, &n);
    return peak_frequency(p, n, rate_hz, min_hz);
}

const std::vector<std::string>& signal_statistic_names() {
    static const std::vector<std::string> names = {
        "mean_x",        "mean_y",        "mean_z",        "gravity_tilt_deg", "sd_x",      "sd_y",      "sd_z",
        "mag_sd",        "mag_p05",       "mag_p50",       "mag_p95",          "mag_rise",  "mag_dip",   "dom_x_hz",
        "dom_y_hz",      "dom_z_hz",      "jerk_rms",      "hf_share",         "hf_sd_x",   "hf_sd_y",   "hf_sd_z",
        "gyr_sway_sd_x", "gyr_sway_sd_y", "gyr_sway_sd_z", "yaw_hz",           "grav_x_re", "grav_x_im", "grav_y_re",
        "grav_y_im",     "grav_z_re",     "grav_z_im"};
    return names;
}

std::map<std::string, double> recording_signal_statistics(const ImuRecording& recording, double rate_hz) {
    const auto channel = [&](size_t column) {  // 0-2 acc, 3-5 gyr, at rate_hz
        std::vector<double> x(recording.samples.size());
        for (size_t i = 0; i < x.size(); ++i) x[i] = recording.samples[i][column];
        return resample_channel(x, recording.rate_hz, rate_hz);
    };
    std::vector<double> axis[3], gyr[3];
    for (size_t a = 0; a < 3; ++a) {
        axis[a] = channel(a);
        gyr[a] = channel(a + 3);
    }
    const size_t n = axis[0].size();
    if (static_cast<double>(n) < kMinSeconds * rate_hz)
        throw Error(recording.path, "samples", "at least 2 s of samples",
                    std::to_string(n) + " at " + std::to_string(rate_hz) + " Hz");
    std::map<std::string, double> s;
    const char* xyz = "xyz";
    Eigen::Vector3d mean;
    double high = 0, total = 0;  // power above kHighFrequencyHz and in all, every axis, DC excluded
    for (int a = 0; a < 3; ++a) {
        mean[a] = mean_of(axis[a]);
        s[std::string("mean_") + xyz[a]] = mean[a];
        s[std::string("sd_") + xyz[a]] = standard_deviation(axis[a]);
        size_t length = 0;
        const std::vector<double> p = periodogram(axis[a], &length);
        s[std::string("dom_") + xyz[a] + "_hz"] = peak_frequency(p, length, rate_hz, kMinDominantHz);
        double axis_high = 0, axis_total = 0;
        for (size_t k = 1; k < p.size(); ++k) {
            axis_total += p[k];
            if (static_cast<double>(k) * rate_hz / static_cast<double>(length) > kHighFrequencyHz) axis_high += p[k];
        }
        s[std::string("hf_sd_") + xyz[a]] =
            axis_total > 0 ? s[std::string("sd_") + xyz[a]] * std::sqrt(axis_high / axis_total) : 0;
        high += axis_high;
        total += axis_total;
    }
    const double largest = mean.cwiseAbs().maxCoeff();
    s["gravity_tilt_deg"] = mean.norm() > 0 ? std::acos(std::min(1.0, largest / mean.norm())) * 180 / M_PI : 0;
    std::vector<double> magnitude(n);
    for (size_t i = 0; i < n; ++i)
        magnitude[i] = std::sqrt(axis[0][i] * axis[0][i] + axis[1][i] * axis[1][i] + axis[2][i] * axis[2][i]);
    s["mag_sd"] = standard_deviation(magnitude);
    s["mag_p05"] = percentile(magnitude, 0.05);
    s["mag_p50"] = percentile(magnitude, 0.5);
    s["mag_p95"] = percentile(magnitude, 0.95);
    const std::vector<double> smooth =
        moving_mean(magnitude, std::max<size_t>(1, static_cast<size_t>(std::lround(kSwingSeconds * rate_hz))));
    s["mag_rise"] = *std::max_element(smooth.begin(), smooth.end()) - s["mag_p50"];
    s["mag_dip"] = s["mag_p50"] - *std::min_element(smooth.begin(), smooth.end());
    double jerk = 0;
    for (size_t i = 1; i < n; ++i) jerk += std::pow((magnitude[i] - magnitude[i - 1]) * rate_hz, 2);
    s["jerk_rms"] = std::sqrt(jerk / static_cast<double>(n - 1));
    s["hf_share"] = total > 0 ? high / total : 0;
    for (int a = 0; a < 3; ++a)
        s[std::string("gyr_sway_sd_") + xyz[a]] = band_sd(gyr[a], rate_hz, kSwayLowHz, kSwayHighHz);
    std::vector<double> yaw_rate(n);  // turning about the up direction (rad/s)
    const Eigen::Vector3d up = mean.norm() > 0 ? Eigen::Vector3d(mean.normalized()) : Eigen::Vector3d::Zero();
    for (size_t i = 0; i < n; ++i) yaw_rate[i] = up.x() * gyr[0][i] + up.y() * gyr[1][i] + up.z() * gyr[2][i];
    s["yaw_hz"] = standard_deviation(yaw_rate) > 0 ? dominant_frequency_hz(yaw_rate, rate_hz, kMinDominantHz) : 0;
    for (int a = 0; a < 3; ++a) {
        const std::complex<double> r = gravity_ratio(axis, gyr, mean, a, rate_hz, s["yaw_hz"]);
        s[std::string("grav_") + xyz[a] + "_re"] = r.real();
        s[std::string("grav_") + xyz[a] + "_im"] = r.imag();
    }
    return s;
}

namespace {

// Recordings at `position`, grouped by evaluation class (coarsened against `other_side` when given).
std::map<std::string, std::vector<std::map<std::string, double>>> statistics_by_activity(
    const std::vector<ImuRecording>& recordings, const std::string& position, double rate_hz,
    const std::set<std::string>* this_side, const std::set<std::string>* other_side) {
    std::map<std::string, std::vector<std::map<std::string, double>>> out;
    for (const ImuRecording& r : recordings) {
        if (!position.empty() && r.position != position) continue;
        std::string label = map_activity(r.dataset, r.activity);
        if (label.empty() || static_cast<double>(r.samples.size()) < kMinSeconds * r.rate_hz) continue;
        if (this_side) label = coarsen_for(label, *this_side, *other_side);
        out[label].push_back(recording_signal_statistics(r, rate_hz));
    }
    return out;
}

std::set<std::string> labels_of(const std::vector<ImuRecording>& recordings, const std::string& position) {
    std::set<std::string> out;
    for (const ImuRecording& r : recordings)
        if (position.empty() || r.position == position) {
            const std::string label = map_activity(r.dataset, r.activity);
            if (!label.empty()) out.insert(label);
        }
    return out;
}

std::vector<double> column(const std::vector<std::map<std::string, double>>& rows, const std::string& name) {
    std::vector<double> v;
    for (const auto& row : rows) v.push_back(row.at(name));
    return v;
}

double median_statistic(const std::vector<std::map<std::string, double>>& rows, const std::string& name) {
    return median_of(column(rows, name));
}

// The interquartile range over 1.349: a normal distribution's sd, robust to a few odd recordings.
double robust_spread(const std::vector<std::map<std::string, double>>& rows, const std::string& name) {
    const std::vector<double> v = column(rows, name);
    return (percentile(v, 0.75) - percentile(v, 0.25)) / 1.349;
}

}  // namespace

void SignalStatisticsOptions::validate() const {
    if (!(rate_hz >= 8 && rate_hz <= 1000)) throw Error("--rate", "rate", "8 to 1000 Hz", std::to_string(rate_hz));
}

nlohmann::json activity_signal_statistics(const std::vector<ImuRecording>& recordings,
                                          const SignalStatisticsOptions& options) {
    options.validate();
    nlohmann::json out = nlohmann::json::object();
    if (!options.position.empty()) check_position_held(recordings, options.position, "--position");
    for (const auto& [activity, rows] :
         statistics_by_activity(recordings, options.position, options.rate_hz, nullptr, nullptr)) {
        nlohmann::json a = {{"recordings", rows.size()}};
        for (const std::string& name : signal_statistic_names()) a[name] = median_statistic(rows, name);
        out[activity] = a;
    }
    return out;
}

SignalStatisticsComparison compare_signal_statistics(const std::vector<ImuRecording>& real,
                                                     const std::vector<ImuRecording>& synthetic,
                                                     const SignalStatisticsOptions& options) {
    options.validate();
    const std::string& position = options.position;
    if (!position.empty()) {
        check_position_held(real, position, "--position");
        check_position_held(synthetic, position, "--position");
    }
    const double rate_hz = options.rate_hz;
    const std::set<std::string> real_labels = labels_of(real, position),
                                synthetic_labels = labels_of(synthetic, position);
    const auto r = statistics_by_activity(real, position, rate_hz, &real_labels, &synthetic_labels);
    const auto s = statistics_by_activity(synthetic, position, rate_hz, &synthetic_labels, &real_labels);
    SignalStatisticsComparison out;
    for (const auto& [activity, real_rows] : r) {
        const auto it = s.find(activity);
        if (it == s.end()) continue;
        ActivityComparison& a = out[activity];
        a.real_recordings = static_cast<int64_t>(real_rows.size()),
        a.synthetic_recordings = static_cast<int64_t>(it->second.size());
        for (const std::string& name : signal_statistic_names()) {
            const double rm = median_statistic(real_rows, name), sm = median_statistic(it->second, name);
            a.statistics[name] = {rm, sm, rm != 0 ? sm / rm : std::nan(""), robust_spread(real_rows, name),
                                  robust_spread(it->second, name)};
        }
    }
    return out;
}

nlohmann::json signal_statistics_comparison_json(const SignalStatisticsComparison& comparison) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [activity, a] : comparison) {
        nlohmann::json j = {{"recordings", {{"real", a.real_recordings}, {"synthetic", a.synthetic_recordings}}}};
        for (const auto& [name, s] : a.statistics)
            j[name] = {{"real", s.real},
                       {"synthetic", s.synthetic},
                       {"ratio", s.ratio},
                       {"real_spread", s.real_spread},
                       {"synthetic_spread", s.synthetic_spread}};
        out[activity] = j;
    }
    return out;
}

namespace {

// A median or ratio JSON wrote as null (NaN) reads back as NaN.
double number_or_nan(const nlohmann::json& doc, const char* key, const std::string& path, const std::string& where) {
    if (doc.is_object() && doc.contains(key) && doc[key].is_null()) return std::nan("");
    return json_number(doc, key, path, where);
}

}  // namespace

SignalStatisticsComparison parse_signal_statistics_comparison(const nlohmann::json& doc, const std::string& path) {
    if (!doc.is_object()) throw Error(path, "json", "an object of activities", doc.dump().substr(0, 40));
    SignalStatisticsComparison out;
    for (const auto& [activity, a] : doc.items()) {
        ActivityComparison& c = out[activity];
        const nlohmann::json& recordings = json_object(a, "recordings", path, activity);
        c.real_recordings = static_cast<int64_t>(json_count(recordings, "real", path, activity + ".recordings"));
        c.synthetic_recordings =
            static_cast<int64_t>(json_count(recordings, "synthetic", path, activity + ".recordings"));
        for (const std::string& name : signal_statistic_names()) {
            if (!a.contains(name)) continue;  // a statistic added since the result was written
            const nlohmann::json& s = json_object(a, name, path, activity);
            const std::string where = activity + "." + name;
            c.statistics[name] = {number_or_nan(s, "real", path, where), number_or_nan(s, "synthetic", path, where),
                                  number_or_nan(s, "ratio", path, where), number_or_nan(s, "real_spread", path, where),
                                  number_or_nan(s, "synthetic_spread", path, where)};
        }
    }
    return out;
}

SignalStatisticsComparison read_signal_statistics_comparison(const std::string& path) {
    return parse_signal_statistics_comparison(read_json_file(path), path);
}

}  // namespace t2imu
