// Synthetic IMU data from real motion capture against real recordings of the same activity: the shipped CMU
// walk (examples/cmu_07_05_slow_walk.bvh) on the paper's average man with HuGaDB's placements, against every
// HuGaDB walking recording (shared data). What is compared: each sensor's mean gravity direction in its own
// frame (checks the mounting conventions), the median and 95th percentile of |acc| (checks the dynamics), and
// the stride frequency at the thigh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>

#include "imu/imu_dataset.hpp"
#include "imu/virtual_imu.hpp"
#include "motion/mocap_import.hpp"
#include "test_util.hpp"

using namespace t2imu;
using Eigen::Vector3d;

namespace {

struct Summary {
    Vector3d mean_acc = Vector3d::Zero();
    double acc_p50 = 0, acc_p95 = 0, stride_hz = 0;
};

double percentile(std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    return v[static_cast<size_t>(q * static_cast<double>(v.size() - 1))];
}

// The frequency in [0.4, 1.6] Hz with the most power in x (a direct DFT at 0.01 Hz steps): walking's
// stride frequency, below the step frequency that dominates vertical acceleration.
double stride_frequency(const std::vector<double>& x, double rate) {
    double mean = 0;
    for (double v : x) mean += v / static_cast<double>(x.size());
    double best = 0, best_f = 0;
    for (double f = 0.4; f <= 1.6; f += 0.01) {
        std::complex<double> s = 0;
        for (size_t k = 0; k < x.size(); ++k)
            s += (x[k] - mean) * std::polar(1.0, -2 * M_PI * f * static_cast<double>(k) / rate);
        if (std::norm(s) > best) best = std::norm(s), best_f = f;
    }
    return best_f;
}

Summary summarise(const std::vector<Vector3d>& acc, const std::vector<Vector3d>& gyr, double rate) {
    Summary s;
    std::vector<double> mag, sagittal;
    for (size_t k = 0; k < acc.size(); ++k) {
        s.mean_acc += acc[k] / static_cast<double>(acc.size());
        mag.push_back(acc[k].norm());
        sagittal.push_back(gyr[k].y());  // HuGaDB's y points to the body's left: the knee/hip flexion axis
    }
    s.acc_p50 = percentile(mag, 0.5);
    s.acc_p95 = percentile(mag, 0.95);
    s.stride_hz = stride_frequency(sagittal, rate);
    return s;
}

}  // namespace

TEST(ImuPlausibility, CmuWalkOnAnAverageManLooksLikeHuGaDBWalking) {
    std::string archive;
    SHARED_OR_SKIP(archive, "imu/hugadb/hugadb.tar.xz");
    const std::string dir = test::unpacked_shared_archive("imu/hugadb/hugadb.tar.xz");
    std::map<std::string, std::vector<Summary>> real;
    for (const ImuRecording& r : read_imu_dataset(dir)) {
        if (r.activity != "walking") continue;
        std::vector<Vector3d> acc, gyr;
        for (const auto& s : r.samples) {
            acc.emplace_back(s[0], s[1], s[2]);
            gyr.emplace_back(s[3], s[4], s[5]);
        }
        real[r.position].push_back(summarise(acc, gyr, r.rate_hz));
    }
    ASSERT_EQ(real.size(), 6u);

    const JointSequence walk = import_motion(test::source_dir() + "/examples/cmu_07_05_slow_walk.bvh");
    const double rate = 58.82;  // HuGaDB's nominal rate
    VirtualImuOptions options;
    options.rate_hz = rate;
    const std::vector<SensorPlacement> sensors = parse_sensor_sets("hugadb");
    const BodyImu imu = synthesize_body_imu(walk, paper_bodies()[2], sensors, options);
    for (size_t i = 0; i < sensors.size(); ++i) {
        const std::string& position = sensors[i].position;
        const Summary syn = summarise(imu.signals[i].acc, imu.signals[i].gyr, rate);
        std::vector<double> p50, p95, stride;
        Vector3d mean_dir = Vector3d::Zero();
        for (const Summary& s : real[position]) {
            p50.push_back(s.acc_p50);
            p95.push_back(s.acc_p95);
            stride.push_back(s.stride_hz);
            mean_dir += s.mean_acc.normalized();
        }
        const double angle =
            std::acos(std::clamp(syn.mean_acc.normalized().dot(mean_dir.normalized()), -1.0, 1.0)) * 180 / M_PI;
        const double real_p50 = percentile(p50, 0.5), real_p95 = percentile(p95, 0.5);
        std::printf(
            "%-11s gravity direction %5.1f deg apart | |acc| p50 %5.2f vs %5.2f, p95 %5.2f vs %5.2f m/s^2 | "
            "stride %.2f vs %.2f Hz (synthetic vs HuGaDB median of %zu)\n",
            position.c_str(), angle, syn.acc_p50, real_p50, syn.acc_p95, real_p95, syn.stride_hz,
            percentile(stride, 0.5), p50.size());
        EXPECT_LT(angle, 30.0) << position;  // the mounting conventions agree with the real sensors
        EXPECT_NEAR(syn.acc_p50 / real_p50, 1.0, 0.25) << position;
        EXPECT_NEAR(syn.acc_p95 / real_p95, 1.0, 0.4) << position;  // HuGaDB clips at 2 g per axis
        if (position.find("thigh") != std::string::npos) {
            EXPECT_GT(syn.stride_hz, 0.5) << position;  // a slow walk: below HuGaDB's normal pace,
            EXPECT_LT(syn.stride_hz, percentile(stride, 0.5) + 0.1) << position;  // but a walking stride
        }
    }
}
