// An interpolating cubic spline through uniformly sampled channels, with "not-a-knot" ends (the third derivative
// is continuous at the second and second-to-last samples, so the end pieces are the cubics the data imply).
// Virtual IMUs need the second derivative of 20 fps positions at 50-100 Hz: a cubic spline gives a continuous,
// piecewise-linear acceleration with an O(h^2) error, where finite differences of resampled frames would give
// steps at every source frame; not-a-knot ends avoid the natural spline's forced zero acceleration (a dip to
// 0 m/s^2 at both clip edges) without inventing curvature beyond the data.
#pragma once
#include <Eigen/Core>

namespace t2imu {

class CubicSpline {
public:
    using Samples = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;  // [n, channels]

    // y: n >= 4 samples at times 0, dt, 2 dt, ...
    CubicSpline(const Samples& y, double dt);

    double duration() const { return dt_ * static_cast<double>(y_.rows() - 1); }
    // Value and first and second derivatives at time t (clamped to [0, duration()]); any pointer may be null.
    void evaluate(double t, Eigen::VectorXd* value, Eigen::VectorXd* d1, Eigen::VectorXd* d2) const;

private:
    Samples y_;
    Samples m_;  // second derivatives at the samples
    double dt_;
};

}  // namespace t2imu
