// PD_PeriodicityWang_th0_01: the periodicity detector of Wang, Smith & Hyndman (2007), as in hctsa.
#include <Eigen/Dense>
#include <cmath>

#include "analysis/catch22_features.hpp"

namespace t2imu::catch22_detail {

// The residual of a least-squares cubic spline with two pieces (breaks at the ends and the middle, twice
// continuously differentiable), Wang et al.'s trend removal. Basis: 1, s, s^2, s^3, (s - 1/2)_+^3 over the time
// index scaled to s in [0, 1], which keeps the normal problem well conditioned.
static Series spline_detrended(const Series& x) {
    const std::size_t n = x.size();
    Eigen::MatrixXd basis(n, 5);
    Eigen::VectorXd y(n);
    for (std::size_t t = 0; t < n; ++t) {
        const double s = static_cast<double>(t) / static_cast<double>(n - 1);
        const double knot = std::max(0.0, s - 0.5);
        basis.row(t) << 1.0, s, s * s, s * s * s, knot * knot * knot;
        y(t) = x[t];
    }
    const Eigen::VectorXd residual = y - basis * basis.colPivHouseholderQr().solve(y);
    return Series(residual.data(), residual.data() + n);
}

// Detrend; autocovariance (mean lagged product) for lags 1..ceil(n/3); find the first peak that has a trough
// before it, rises above that trough by at least `threshold` and is positive. The reference reports the
// peak's 0-based position in that list of lags, i.e. its lag minus one (0 when there is no such peak); the
// outputs are kept comparable with it.
double periodicity_wang(const Series& x, double threshold) {
    const Series y = spline_detrended(x);
    const std::size_t n = y.size(), max_lag = (n + 2) / 3;
    Series acf(max_lag);  // acf[i] is lag i + 1
    for (std::size_t lag = 1; lag <= max_lag; ++lag) {
        double sum = 0.0;
        for (std::size_t t = 0; t + lag < n; ++t) sum += y[t] * y[t + lag];
        acf[lag - 1] = sum / static_cast<double>(n - lag);
    }
    bool have_trough = false;
    double trough = 0.0;
    for (std::size_t i = 1; i + 1 < max_lag; ++i) {
        const double before = acf[i] - acf[i - 1], after = acf[i + 1] - acf[i];
        if (before < 0.0 && after > 0.0) {
            have_trough = true;
            trough = acf[i];
        } else if (before > 0.0 && after < 0.0 && have_trough && acf[i] - trough >= threshold && acf[i] > 0.0) {
            return static_cast<double>(i);
        }
    }
    return 0.0;
}

}  // namespace t2imu::catch22_detail
