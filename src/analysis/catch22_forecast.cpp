// Simple local forecasting features: FC_LocalSimple_mean3_stderr and FC_LocalSimple_mean1_tauresrat.
#include "analysis/catch22_features.hpp"

namespace t2imu::catch22_detail {

// Residuals of predicting each value by the mean of the `window` values before it.
static Series local_mean_residuals(const Series& x, std::size_t window) {
    Series residuals(x.size() - window);
    for (std::size_t t = window; t < x.size(); ++t) {
        double sum = 0.0;
        for (std::size_t k = t - window; k < t; ++k) sum += x[k];
        residuals[t - window] = x[t] - sum / static_cast<double>(window);
    }
    return residuals;
}

// FC_LocalSimple_mean3_stderr: the standard deviation of the residuals of the 3-sample running-mean forecast.
double local_mean3_stderr(const Series& x) { return sample_std(local_mean_residuals(x, 3)); }

// FC_LocalSimple_mean1_tauresrat: how much the 1-sample (previous value) forecast whitens the series: the first
// zero crossing of the residuals' autocorrelation over that of the series'.
double local_mean1_tauresrat(const Series& x, const Series& acf) {
    const Series residuals = local_mean_residuals(x, 1);
    return static_cast<double>(first_zero_crossing(autocorrelation(residuals))) /
           static_cast<double>(first_zero_crossing(acf));
}

}  // namespace t2imu::catch22_detail
