// Foot landings (motion/foot_landings): one per step in walking, on the level and on stairs, without a floor
// height; none standing still.
#include <gtest/gtest.h>

#include <cmath>

#include "motion/foot_landings.hpp"
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
            const double y =
                0.1 * std::sin(M_PI * std::min(1.0, swing)) * (phase < 0.5) + rise_per_step * (cycles + swing);
            s.at(f, side == 0 ? left_ankle : right_ankle) = Eigen::Vector3d(side ? -0.1 : 0.1, 0.08 + y, z);
        }
    }
    return s;
}

}  // namespace

TEST(FootLandings, FindsOneLandingPerStepOnTheLevelAndOnStairs) {
    for (double rise : {0.0, 0.17}) {
        const JointSequence walk = stepping(20, 121, rise);  // 6 s: 10 landings per foot, minus the first half-cycle
        const std::vector<Landing> landings = detect_landings(walk);
        ASSERT_GE(landings.size(), 17u) << rise;
        ASSERT_LE(landings.size(), 20u) << rise;
        for (size_t i = 1; i < landings.size(); ++i)
            EXPECT_NEAR(landings[i].time_s - landings[i - 1].time_s, 0.3, 0.051) << rise;
    }
}

TEST(FootLandings, StandingStillHasNoLandings) {
    JointSequence still(80, kNumJoints, 20);
    for (int f = 0; f < 80; ++f)
        for (int j = 0; j < kNumJoints; ++j) still.at(f, j) = Eigen::Vector3d(0.01 * j, 0.05 * j, 0);
    EXPECT_TRUE(detect_landings(still).empty());
}
