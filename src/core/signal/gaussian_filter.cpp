#include "core/signal/gaussian_filter.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace t2imu {

TimeSeries gaussian_filter1d_nearest(const TimeSeries& x, double sigma, double truncate) {
    const int radius = static_cast<int>(truncate * sigma + 0.5);
    std::vector<double> w(static_cast<size_t>(2 * radius + 1));
    double sum = 0;
    for (int k = -radius; k <= radius; ++k)
        sum += w[static_cast<size_t>(k + radius)] = std::exp(-0.5 * k * k / (sigma * sigma));
    for (double& v : w) v /= sum;

    const int n = static_cast<int>(x.rows());
    TimeSeries y = TimeSeries::Zero(x.rows(), x.cols());
    for (int t = 0; t < n; ++t)
        for (int k = -radius; k <= radius; ++k) {
            const int s = std::clamp(t + k, 0, n - 1);
            y.row(t) += w[static_cast<size_t>(k + radius)] * x.row(s);
        }
    return y;
}

}  // namespace t2imu
