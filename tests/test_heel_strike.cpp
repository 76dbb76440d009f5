// Landing transients (imu/heel_strike): pulses that leave velocity and path unchanged, transmissibility falling from
// shank to head.
#include <gtest/gtest.h>

#include <cmath>

#include "imu/heel_strike.hpp"
#include "motion/skeleton.hpp"

using namespace t2imu;
using namespace t2imu::smpl22;

TEST(HeelStrike, PulseKeepsVelocityAndPositionButHasItsSharpPeak) {
    const std::vector<Landing> landings = {{1.0}};
    const ImpactPulses p = impact_pulses(landings, 1.0, 0.04, pelvis, 20);
    ASSERT_EQ(p.delta_v.size(), 1u);
    EXPECT_NEAR((p.delta_v[0] - Eigen::Vector3d(0, 0.4, 0)).norm(), 0,
                1e-12);  // 1 m/s at the shank, 0.4 of it at the pelvis
    const double dt = 1e-5;
    double v = 0, x = 0, peak = 0;
    for (double t = 0; t < 2.0; t += dt) {
        const double a = p.acceleration(t).y();
        EXPECT_EQ(p.acceleration(t).x(), 0);
        v += a * dt;
        x += v * dt;
        peak = std::max(peak, a);
    }
    EXPECT_NEAR(v, 0, 1e-6);  // zero area: the velocity after the landing is the motion's own
    EXPECT_NEAR(x, 0, 1e-6);  // zero first moment: so is the path
    // The half-sine peaks at pi/(2 d) delta_v, less the spread Gaussian's peak at the same centre.
    EXPECT_NEAR(peak, 0.4 * (M_PI / 0.08 - 1 / (0.05 * std::sqrt(2 * M_PI))), 1e-3);
}

TEST(HeelStrike, TransmissibilityFallsFromShankToHead) {
    EXPECT_EQ(landing_transmissibility(left_knee), 1.0);
    EXPECT_GT(landing_transmissibility(left_hip), landing_transmissibility(pelvis));
    EXPECT_GT(landing_transmissibility(pelvis), landing_transmissibility(spine3));
    EXPECT_GT(landing_transmissibility(spine3), landing_transmissibility(head));
    EXPECT_GT(landing_transmissibility(head), landing_transmissibility(left_elbow));
}

TEST(HeelStrike, SpreadLandingsFollowTheirDistributions) {
    std::vector<Landing> landings;
    for (int i = 0; i < 4000; ++i) landings.push_back({0.5 * i});
    const ImpactPulses p = impact_pulses(landings, 1.0, 0.04, pelvis, 20, {0.3, 0.8}, 11);
    // log(vertical / 0.4) ~ N(0, 0.3); each horizontal component / vertical ~ N(0, 0.8). Standard errors with
    // n = 4000: mean sd/63, sd sd/89.
    double sum = 0, sum2 = 0, hx2 = 0, hz2 = 0;
    for (const Eigen::Vector3d& dv : p.delta_v) {
        const double l = std::log(dv.y() / 0.4);
        sum += l, sum2 += l * l;
        hx2 += std::pow(dv.x() / dv.y(), 2), hz2 += std::pow(dv.z() / dv.y(), 2);
    }
    const double n = static_cast<double>(p.delta_v.size());
    EXPECT_NEAR(sum / n, 0, 4 * 0.3 / 63);
    EXPECT_NEAR(std::sqrt(sum2 / n - std::pow(sum / n, 2)), 0.3, 4 * 0.3 / 89);
    EXPECT_NEAR(std::sqrt(hx2 / n), 0.8, 4 * 0.8 / 89);
    EXPECT_NEAR(std::sqrt(hz2 / n), 0.8, 4 * 0.8 / 89);
    // Seeded: the same draws again, others from another seed. Each pulse still has zero area in every axis.
    EXPECT_EQ(impact_pulses(landings, 1.0, 0.04, pelvis, 20, {0.3, 0.8}, 11).delta_v[7], p.delta_v[7]);
    EXPECT_NE(impact_pulses(landings, 1.0, 0.04, pelvis, 20, {0.3, 0.8}, 12).delta_v[7], p.delta_v[7]);
    const ImpactPulses one = impact_pulses({{1.0}}, 1.0, 0.04, pelvis, 20, {0.3, 0.8}, 11);
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    for (double t = 0; t < 2.0; t += 1e-5) v += one.acceleration(t) * 1e-5;
    EXPECT_LT(v.norm(), 1e-6);
}
