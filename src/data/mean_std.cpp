#include "data/mean_std.hpp"

#include <cmath>

#include "core/error.hpp"

namespace t2imu {

FeatureStats compute_mean_std(const std::vector<FeatureMatrix>& clips) {
    if (clips.empty()) throw Error("Mean/Std", "clips", "at least one clip");
    const Eigen::Index c = clips[0].cols();
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(c), sq = Eigen::VectorXd::Zero(c);
    double n = 0;
    for (const FeatureMatrix& m : clips) {
        if (m.cols() != c) throw Error("Mean/Std", "channels", std::to_string(c), std::to_string(m.cols()));
        sum += m.colwise().sum().transpose();
        n += static_cast<double>(m.rows());
    }
    const Eigen::VectorXd mean = sum / n;
    for (const FeatureMatrix& m : clips)
        sq += (m.rowwise() - mean.transpose()).array().square().colwise().sum().matrix().transpose();
    Eigen::VectorXd std = (sq / n).array().sqrt();
    if (c == 263) {
        const int groups[][2] = {{0, 1}, {1, 3}, {3, 4}, {4, 67}, {67, 193}, {193, 259}, {259, 263}};
        for (const auto& g : groups) {
            const double s = std.segment(g[0], g[1] - g[0]).mean();
            std.segment(g[0], g[1] - g[0]).setConstant(s > 0 ? s : 1.0);
        }
    }
    return {mean, std};
}

}  // namespace t2imu
