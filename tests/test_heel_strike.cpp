// Landing transients (imu/heel_strike): landings found in walking without a floor height, pulses that leave
// velocity and path unchanged, transmissibility falling from shank to head.
#include <gtest/gtest.h>

#include <cmath>

#include "imu/heel_strike.hpp"
#include "motion/skeleton.hpp"

using namespace t2imu;
using namespace t2imu::smpl22;

namespace {

// Two ankles stepping alternately: each foot swings 0.3 s (1.2 m forward, lifted 0.1 m) and stands 0.3 s;
// the right foot half a cycle after the left. Other joints ride along with the pelvis.
JointSequence stepping(double fps, int frames, double rise_per_step = 0) {
    JointSequence s(frames, kNumJoints, fps);
    for (int f = 0; f < frames; ++f) {
        const double t = f / fps;
        for (int j = 0; j < kNumJoints; ++j) s.at(f, j) = Eigen::Vector3d(0, 0.9, 2.0 * t);
        for (int side = 0; side < 2; ++side) {
            const double phase = std::fmod(t / 0.6 + 0.5 * side, 1.0);  // 0-0.5 swing, 0.5-1 stance
            const double cycles = std::floor(t / 0.6 + 0.5 * side);
            const double swing = phase < 0.5 ? phase / 0.5 : 1.0;
            const double z = 1.2 * (cycles + swing);
            const double y = 0.1 * std::sin(M_PI * std::min(1.0, swing)) * (phase < 0.5) + rise_per_step * (cycles + swing);
            s.at(f, side == 0 ? left_ankle : right_ankle) = Eigen::Vector3d(side ? -0.1 : 0.1, 0.08 + y, z);
        }
    }
    return s;
}

}  // namespace

TEST(HeelStrike, FindsOneLandingPerStepOnTheLevelAndOnStairs) {
    for (double rise : {0.0, 0.17}) {
        const JointSequence walk = stepping(20, 121, rise);  // 6 s: 10 landings per foot, minus the first half-cycle
        const std::vector<Landing> landings = detect_landings(walk);
        ASSERT_GE(landings.size(), 17u) << rise;
        ASSERT_LE(landings.size(), 20u) << rise;
        for (size_t i = 1; i < landings.size(); ++i) EXPECT_NEAR(landings[i].time_s - landings[i - 1].time_s, 0.3, 0.051) << rise;
    }
}

TEST(HeelStrike, StandingStillHasNoLandings) {
    JointSequence still(80, kNumJoints, 20);
    for (int f = 0; f < 80; ++f)
        for (int j = 0; j < kNumJoints; ++j) still.at(f, j) = Eigen::Vector3d(0.01 * j, 0.05 * j, 0);
    EXPECT_TRUE(detect_landings(still).empty());
}

TEST(HeelStrike, PulseKeepsVelocityAndPositionButHasItsSharpPeak) {
    const std::vector<Landing> landings = {{1.0}};
    const ImpactPulses p = impact_pulses(landings, 1.0, 0.04, pelvis, 20);
    ASSERT_EQ(p.delta_v.size(), 1u);
    EXPECT_NEAR((p.delta_v[0] - Eigen::Vector3d(0, 0.4, 0)).norm(), 0, 1e-12);  // 1 m/s at the shank, 0.4 of it at the pelvis
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
