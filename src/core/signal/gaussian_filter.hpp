// A 1-D Gaussian filter along time with the semantics of scipy.ndimage.gaussian_filter1d(x, sigma, axis=0,
// mode='nearest', truncate=4.0), which HumanML3D uses to smooth the body's forward direction (sigma = 20
// frames). The kernel has radius int(truncate * sigma + 0.5) and sums to 1; samples beyond the ends repeat the
// edge sample.
#pragma once
#include <Eigen/Core>

namespace t2imu {

using TimeSeries = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;  // [frames, channels]

TimeSeries gaussian_filter1d_nearest(const TimeSeries& x, double sigma, double truncate = 4.0);

}  // namespace t2imu
