#include "imu/sensor_noise.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "core/parse.hpp"
#include "imu/dataset_profile.hpp"

namespace t2imu {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

constexpr double kG = 9.80665, kDeg = M_PI / 180;

}  // namespace

SensorNoiseModel smartphone_sensor() {
    SensorNoiseModel m;
    m.acc_noise_density = 180e-6 * kG;
    m.gyr_noise_density = 0.007 * kDeg;
    m.acc_bias_sd = 0.040 * kG;
    m.gyr_bias_sd = 1.0 * kDeg;
    m.acc_bias_walk = 1e-4;
    m.gyr_bias_walk = 1e-5;
    m.scale_sd = 0.01;
    m.misalignment_sd_rad = 0.5 * kDeg;
    m.acc_range = 8 * kG;
    m.gyr_range = 2000 * kDeg;
    m.bits = 16;
    m.name = "smartphone";
    return m;
}

namespace {

// none, smartphone, or a data set's device (dataset_profile.hpp).
SensorNoiseModel preset(const std::string& name, const std::string& option) {
    if (name == "none") return SensorNoiseModel();
    if (name == "smartphone") return smartphone_sensor();
    const DatasetProfile* profile = find_dataset_profile(name);
    if (!profile) throw Error(option, "model", "none, smartphone, " + dataset_profile_names(), name);
    return profile->sensor;
}

void set_field(SensorNoiseModel& m, const std::string& key, double v, const std::string& option) {
    if (key == "acc_noise_density")
        m.acc_noise_density = v;
    else if (key == "gyr_noise_density")
        m.gyr_noise_density = v;
    else if (key == "acc_bias_sd")
        m.acc_bias_sd = v;
    else if (key == "gyr_bias_sd")
        m.gyr_bias_sd = v;
    else if (key == "acc_bias_walk")
        m.acc_bias_walk = v;
    else if (key == "gyr_bias_walk")
        m.gyr_bias_walk = v;
    else if (key == "scale_sd")
        m.scale_sd = v;
    else if (key == "misalignment_deg")
        m.misalignment_sd_rad = v * kDeg;
    else if (key == "acc_range_g")
        m.acc_range = v * kG;
    else if (key == "gyr_range_dps")
        m.gyr_range = v * kDeg;
    else if (key == "bits")
        m.bits = static_cast<int>(v);
    else
        throw Error(
            option, key,
            "a field of the noise model (acc_noise_density, gyr_noise_density, acc_bias_sd, "
            "gyr_bias_sd, acc_bias_walk, gyr_bias_walk, scale_sd, misalignment_deg, acc_range_g, gyr_range_dps, bits)");
}

struct AxisErrors {
    Matrix3d gain;  // (I + scale)(I + misalignment)
    Vector3d bias;
};

AxisErrors draw_axis_errors(const SensorNoiseModel& m, double bias_sd, std::mt19937_64& rng) {
    std::normal_distribution<double> n;
    Matrix3d scale = Matrix3d::Identity(), mis = Matrix3d::Identity();
    for (int a = 0; a < 3; ++a) scale(a, a) += m.scale_sd * n(rng);
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            if (a != b) mis(a, b) = m.misalignment_sd_rad * n(rng);  // small angles: sin(x) ~ x
    Vector3d bias(n(rng), n(rng), n(rng));
    return {scale * mis, bias_sd * bias};
}

double quantise_clip(double v, double range, int bits) {
    if (range > 0) v = std::clamp(v, -range, range);
    if (bits > 0 && range > 0) {
        const double lsb = 2 * range / std::ldexp(1.0, bits);
        v = std::round(v / lsb) * lsb;
    }
    return v;
}

void corrupt(std::vector<Vector3d>& x, const AxisErrors& e, double density, double walk, double range, int bits,
             double rate, std::mt19937_64& rng) {
    std::normal_distribution<double> n;
    const double white_sd = density * std::sqrt(rate), walk_sd = walk / std::sqrt(rate);
    Vector3d bias = e.bias;
    for (Vector3d& v : x) {
        v = e.gain * v + bias + white_sd * Vector3d(n(rng), n(rng), n(rng));
        for (int a = 0; a < 3; ++a) v[a] = quantise_clip(v[a], range, bits);
        bias += walk_sd * Vector3d(n(rng), n(rng), n(rng));
    }
}

std::atomic<int64_t> noise_model_parses{0};  // noise_model_parse_count()

}  // namespace

int64_t noise_model_parse_count() { return noise_model_parses.load(); }

SensorNoiseModel parse_noise_model(const std::string& text, const std::string& option) {
    ++noise_model_parses;
    const NamedOverrides spelled = parse_named_overrides(text, option);
    SensorNoiseModel m = preset(spelled.name, option);
    for (const auto& [key, value] : spelled.overrides) {
        const std::optional<double> v = parse_finite(value);
        if (!v || *v < 0) throw Error(option, key, "a non-negative number", value);
        set_field(m, key, *v, option);
    }
    if (m.name == "none" && text != "none") throw Error(option, "none", "no overrides");
    return m;
}

void apply_sensor_noise(const SensorNoiseModel& m, uint64_t seed, ImuSignals* s) {
    if (!m.enabled()) return;
    std::mt19937_64 rng(seed);
    const AxisErrors acc = draw_axis_errors(m, m.acc_bias_sd, rng);
    const AxisErrors gyr = draw_axis_errors(m, m.gyr_bias_sd, rng);
    corrupt(s->acc, acc, m.acc_noise_density, m.acc_bias_walk, m.acc_range, m.bits, s->rate_hz, rng);
    corrupt(s->gyr, gyr, m.gyr_noise_density, m.gyr_bias_walk, m.gyr_range, m.bits, s->rate_hz, rng);
}

}  // namespace t2imu
