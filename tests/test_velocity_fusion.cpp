// velocity_fusion.cpp: features made from a motion (positions and velocities consistent) come back unchanged; a
// flicker of the positions alone is removed; the filter's gain on a sine in the positions is w / (w + 4 sin^2(pi f /
// fps)), the complementary filter's; crossovers outside (0, fps / 2) and features of another shape are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "motion/humanml3d.hpp"
#include "motion/velocity_fusion.hpp"
#include "test_util.hpp"
#include "walk_fixture.hpp"

using namespace t2imu;

namespace {

// Over frames [from, num_frames - from).
double max_height_difference(const JointSequence& a, const JointSequence& b, int from = 0) {
    double d = 0;
    for (int f = from; f < a.num_frames - from; ++f)
        for (int j = 0; j < a.num_joints; ++j) d = std::max(d, std::fabs(a.at(f, j).y() - b.at(f, j).y()));
    return d;
}

}  // namespace

TEST(VelocityFusion, ConsistentFeaturesComeBackUnchanged) {
    const FeatureMatrix features = joints_to_features(test::procedural_walk(4.0));
    const JointSequence ric = recover_from_ric(features);
    const JointSequence fused = fuse_joint_heights(ric, features, 1.0);
    EXPECT_LT(max_height_difference(fused, ric), 1e-9);
    for (int f = 0; f < ric.num_frames; ++f)  // the horizontal positions are not touched
        for (int j = 0; j < ric.num_joints; ++j) {
            EXPECT_EQ(fused.at(f, j).x(), ric.at(f, j).x());
            EXPECT_EQ(fused.at(f, j).z(), ric.at(f, j).z());
        }
    EXPECT_LT(max_height_difference(joints_from_features(features, 1.0), ric), 1e-9);
    EXPECT_EQ(max_height_difference(joints_from_features(features, 0), ric), 0);  // off: recover_from_ric
}

// The flicker of the positions at the frame rate's Nyquist frequency (every joint up and down 2 cm on alternate
// frames, the velocities untouched) passes with the gain w / (w + 4): at 1 Hz about 2.4 %; the first and last frames,
// held by one velocity each, keep more of it.
TEST(VelocityFusion, AFlickerOfThePositionsAloneIsRemoved) {
    FeatureMatrix features = joints_to_features(test::procedural_walk(4.0));
    const JointSequence clean = recover_from_ric(features);
    for (Eigen::Index f = 0; f < features.rows(); ++f) {
        const double flicker = f % 2 ? 0.02 : -0.02;
        features(f, 3) += flicker;  // the root's height
        for (int j = 1; j < 22; ++j) features(f, 4 + 3 * (j - 1) + 1) += flicker;
    }
    const JointSequence flickering = recover_from_ric(features);
    EXPECT_NEAR(max_height_difference(flickering, clean), 0.02, 1e-12);
    const double w = 4 * std::pow(std::sin(M_PI * 1.0 / 20), 2);
    const JointSequence fused = fuse_joint_heights(flickering, features, 1.0);
    EXPECT_LT(max_height_difference(fused, clean, 20), 0.02 * 1.1 * w / (w + 4));
    EXPECT_LT(max_height_difference(fused, clean), 0.02 * 0.2);
}

// A sine of frequency f in the positions with zero velocities: away from the ends its amplitude is scaled by the
// filter's gain (the minimiser's frequency response).
TEST(VelocityFusion, GainOnThePositionsIsTheComplementaryFiltersLowPass) {
    const int frames = 400;
    for (const auto& [f_hz, crossover_hz] : {std::pair{5.0, 1.0}, {1.0, 1.0}, {0.25, 2.0}}) {
        JointSequence joints(frames, 22, 20);
        FeatureMatrix features = FeatureMatrix::Zero(frames, 263);
        for (int f = 0; f < frames; ++f)
            for (int j = 0; j < 22; ++j) joints.at(f, j) = {0, 1 + 0.1 * std::sin(2 * M_PI * f_hz * f / 20), 0};
        const JointSequence fused = fuse_joint_heights(joints, features, crossover_hz);
        double amplitude = 0;
        for (int f = 150; f < 250; ++f) amplitude = std::max(amplitude, std::fabs(fused.at(f, 5).y() - 1));
        const double w = 4 * std::pow(std::sin(M_PI * crossover_hz / 20), 2);
        const double gain = w / (w + 4 * std::pow(std::sin(M_PI * f_hz / 20), 2));
        EXPECT_NEAR(amplitude, 0.1 * gain, 0.1 * gain * 0.02) << f_hz << " Hz, crossover " << crossover_hz;
    }
}

TEST(VelocityFusion, RefusesACrossoverOutOfRangeAndFeaturesOfAnotherShape) {
    const FeatureMatrix features = joints_to_features(test::procedural_walk(2.0));
    const JointSequence joints = recover_from_ric(features);
    for (double hz : {0.0, -1.0, 10.0, std::numeric_limits<double>::quiet_NaN()})
        EXPECT_TRUE(test::contains(test::error_message([&] { fuse_joint_heights(joints, features, hz); }),
                                   "--height-crossover"))
            << hz;
    const FeatureMatrix shorter = features.topRows(features.rows() - 1);
    EXPECT_TRUE(test::contains(test::error_message([&] { fuse_joint_heights(joints, shorter, 1.0); }), "features"));
}
