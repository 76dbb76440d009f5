#include "imu/device_rate.hpp"

#include <cmath>
#include <numeric>

#include "core/error.hpp"
#include "core/signal/resample_poly.hpp"

namespace t2imu {

ImuSignals resample_imu_signals(const ImuSignals& s, double rate_hz) {
    if (s.rate_hz == rate_hz || s.t.empty()) return s;
    const long in = std::lround(s.rate_hz), out = std::lround(rate_hz);
    if (std::fabs(s.rate_hz - static_cast<double>(in)) > 1e-9 || std::fabs(rate_hz - static_cast<double>(out)) > 1e-9 ||
        in <= 0 || out <= 0)
        throw Error("--rate", "rate", "whole numbers of Hz for the device's rate and the output's",
                    std::to_string(s.rate_hz) + " and " + std::to_string(rate_hz));
    const long g = std::gcd(in, out);
    const int up = static_cast<int>(out / g), down = static_cast<int>(in / g);
    // No sample past the last input instant: the resampler's tail would be the edge padding's line.
    const size_t n =
        static_cast<size_t>(std::floor(
            static_cast<double>(s.t.size() - 1) * static_cast<double>(out) / static_cast<double>(in) + 1e-9)) +
        1;
    ImuSignals r;
    r.rate_hz = rate_hz;
    r.acc.assign(n, Eigen::Vector3d::Zero());
    r.gyr.assign(n, Eigen::Vector3d::Zero());
    for (int axis = 0; axis < 6; ++axis) {
        std::vector<double> x(s.t.size());
        for (size_t k = 0; k < x.size(); ++k) x[k] = axis < 3 ? s.acc[k][axis] : s.gyr[k][axis - 3];
        const std::vector<double> y = resample_poly(x, up, down);
        for (size_t k = 0; k < n; ++k) (axis < 3 ? r.acc[k][axis] : r.gyr[k][axis - 3]) = y[k];
    }
    for (size_t k = 0; k < n; ++k) r.t.push_back(s.t.front() + static_cast<double>(k) / rate_hz);
    return r;
}

}  // namespace t2imu
