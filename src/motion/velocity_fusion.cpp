#include "motion/velocity_fusion.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "motion/humanml3d.hpp"

namespace t2imu {

namespace {

constexpr int kVelocityChannel = 193;  // joint j's local velocity: 193 + 3 j .. + 2

// Solves (w I + D^T D) x = w p + D^T v for D the forward difference [F-1, F] (Thomas algorithm; the matrix is
// symmetric, diagonally dominant for w > 0).
std::vector<double> fuse_series(const std::vector<double>& p, const std::vector<double>& v, double w) {
    const size_t n = p.size();
    std::vector<double> diag(n, w), off(n, 0.0), rhs(n);
    for (size_t t = 0; t < n; ++t) rhs[t] = w * p[t];
    for (size_t t = 0; t + 1 < n; ++t) {
        diag[t] += 1, diag[t + 1] += 1, off[t] = -1;  // off[t]: the entry (t, t+1) and (t+1, t)
        rhs[t] -= v[t], rhs[t + 1] += v[t];
    }
    for (size_t t = 1; t < n; ++t) {
        const double m = off[t - 1] / diag[t - 1];
        diag[t] -= m * off[t - 1];
        rhs[t] -= m * rhs[t - 1];
    }
    std::vector<double> x(n);
    x[n - 1] = rhs[n - 1] / diag[n - 1];
    for (size_t t = n - 1; t-- > 0;) x[t] = (rhs[t] - off[t] * x[t + 1]) / diag[t];
    return x;
}

}  // namespace

JointSequence fuse_joint_heights(const JointSequence& joints, const FeatureMatrix& features, double crossover_hz) {
    const double fps = joints.fps;
    if (!(crossover_hz > 0 && crossover_hz < fps / 2))
        throw Error("--height-crossover", "crossover", "above 0 Hz, below half the frame rate",
                    std::to_string(crossover_hz));
    if (features.cols() != 263 || features.rows() != joints.num_frames || joints.num_joints != 22)
        throw Error("fuse_joint_heights", "features", "[F, 263] features of the joints' F frames",
                    std::to_string(features.rows()) + " x " + std::to_string(features.cols()));
    const double s = std::sin(M_PI * crossover_hz / fps);
    const double w = 4 * s * s;
    JointSequence out = joints;
    const int n = joints.num_frames;
    if (n < 2) return out;
    std::vector<double> p(static_cast<size_t>(n)), v(static_cast<size_t>(n - 1));
    for (int j = 0; j < joints.num_joints; ++j) {
        for (int f = 0; f < n; ++f) p[static_cast<size_t>(f)] = joints.at(f, j).y();
        for (int f = 0; f + 1 < n; ++f) v[static_cast<size_t>(f)] = features(f, kVelocityChannel + 3 * j + 1);
        const std::vector<double> x = fuse_series(p, v, w);
        for (int f = 0; f < n; ++f) out.at(f, j).y() = x[static_cast<size_t>(f)];
    }
    return out;
}

JointSequence joints_from_features(const FeatureMatrix& features, double crossover_hz) {
    const JointSequence joints = recover_from_ric(features);
    return crossover_hz > 0 ? fuse_joint_heights(joints, features, crossover_hz) : joints;
}

}  // namespace t2imu
