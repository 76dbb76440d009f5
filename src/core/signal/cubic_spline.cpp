#include "core/signal/cubic_spline.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace t2imu {

CubicSpline::CubicSpline(const Samples& y, double dt) : y_(y), dt_(dt) {
    const Eigen::Index n = y.rows();
    if (n < 4) throw Error("spline", "samples", "at least 4", std::to_string(n));
    if (!(dt > 0)) throw Error("spline", "dt", "a positive sample spacing");
    // Interior rows: M[i-1] + 4 M[i] + M[i+1] = 6 / dt^2 (y[i-1] - 2 y[i] + y[i+1]). Not-a-knot on a uniform grid
    // means M0 = 2 M1 - M2 and M[n-1] = 2 M[n-2] - M[n-3], which turn rows 1 and n-2 into 6 M = rhs.
    Samples rhs = Samples::Zero(n, y.cols());
    for (Eigen::Index i = 1; i + 1 < n; ++i)
        rhs.row(i) = 6.0 / (dt * dt) * (y.row(i - 1) - 2.0 * y.row(i) + y.row(i + 1));
    m_ = Samples::Zero(n, y.cols());
    m_.row(1) = rhs.row(1) / 6.0;
    m_.row(n - 2) = rhs.row(n - 2) / 6.0;
    if (n > 4) {
        // Thomas algorithm on rows 2..n-3 (diagonal 4, off-diagonals 1), with M1 and M[n-2] known.
        const Eigen::Index k = n - 4;
        std::vector<double> c(static_cast<size_t>(k));
        Samples d(k, y.cols());
        for (Eigen::Index r = 0; r < k; ++r) {
            Eigen::RowVectorXd b = rhs.row(r + 2);
            if (r == 0) b -= m_.row(1);
            if (r == k - 1) b -= m_.row(n - 2);
            const double denom = 4.0 - (r > 0 ? c[static_cast<size_t>(r - 1)] : 0.0);
            c[static_cast<size_t>(r)] = 1.0 / denom;
            d.row(r) = (b - (r > 0 ? Eigen::RowVectorXd(d.row(r - 1)) : Eigen::RowVectorXd::Zero(y.cols()))) / denom;
        }
        for (Eigen::Index r = k - 1; r >= 0; --r) {
            m_.row(r + 2) = d.row(r);
            if (r < k - 1) m_.row(r + 2) -= c[static_cast<size_t>(r)] * m_.row(r + 3);
        }
    }
    m_.row(0) = 2.0 * m_.row(1) - m_.row(2);
    m_.row(n - 1) = 2.0 * m_.row(n - 2) - m_.row(n - 3);
}

void CubicSpline::evaluate(double t, Eigen::VectorXd* value, Eigen::VectorXd* d1, Eigen::VectorXd* d2) const {
    const Eigen::Index n = y_.rows();
    t = std::clamp(t, 0.0, duration());
    const Eigen::Index i = std::min<Eigen::Index>(static_cast<Eigen::Index>(t / dt_), n - 2);
    const double h = dt_, a = (static_cast<double>(i + 1) * h - t), b = (t - static_cast<double>(i) * h);
    const auto y0 = y_.row(i).transpose(), y1 = y_.row(i + 1).transpose();
    const auto m0 = m_.row(i).transpose(), m1 = m_.row(i + 1).transpose();
    if (value)
        *value = m0 * (a * a * a) / (6 * h) + m1 * (b * b * b) / (6 * h) + (y0 / h - m0 * h / 6) * a +
                 (y1 / h - m1 * h / 6) * b;
    if (d1) *d1 = -m0 * (a * a) / (2 * h) + m1 * (b * b) / (2 * h) - (y0 / h - m0 * h / 6) + (y1 / h - m1 * h / 6);
    if (d2) *d2 = m0 * (a / h) + m1 * (b / h);
}

}  // namespace t2imu
