// JointSequence's array round trip, its refusals (each naming the source and field), frame slicing and the
// frame-rate check every command that reads joints uses.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "motion/joint_sequence.hpp"
#include "test_util.hpp"

using namespace t2imu;

TEST(JointSequence, ArrayRoundTripKeepsEveryPositionAndTheRate) {
    std::vector<float> values(5 * 22 * 3);
    for (size_t i = 0; i < values.size(); ++i) values[i] = 0.01f * static_cast<float>(i);
    const JointSequence s = joint_sequence_from_array(NdArray::from(values, {5, 22, 3}), "x.npy", 22, 1, 30.0);
    EXPECT_EQ(s.num_frames, 5);
    EXPECT_DOUBLE_EQ(s.fps, 30.0);
    EXPECT_FLOAT_EQ(static_cast<float>(s.at(4, 21).z()), values.back());
    const NdArray back = joint_sequence_to_array(s);
    EXPECT_EQ(back.shape, (std::vector<int64_t>{5, 22, 3}));
    const JointSequence again = joint_sequence_from_array(back, "back");
    for (size_t i = 0; i < s.positions.size(); ++i) EXPECT_EQ(again.positions[i], s.positions[i]);
}

TEST(JointSequence, BadArraysAreRefusedNamingTheSourceAndField) {
    const auto refusal = [](const NdArray& a, int min_frames) {
        return test::error_message([&] { joint_sequence_from_array(a, "in.npy", 22, min_frames); });
    };
    std::vector<float> v(2 * 22 * 3, 0.f);
    EXPECT_NE(refusal(NdArray::from(v, {2, 66}), 1).find("in.npy: shape"), std::string::npos);
    EXPECT_NE(refusal(NdArray::from(v, {2, 33, 2}), 1).find("in.npy: shape"), std::string::npos);
    EXPECT_NE(refusal(NdArray::from(v, {2, 22, 3}), 4).find("at least 4 frames"), std::string::npos);
    v[7] = std::nanf("");
    EXPECT_NE(refusal(NdArray::from(v, {2, 22, 3}), 1).find("NaN or inf at flat index 7"), std::string::npos);
}

TEST(JointSequence, SliceKeepsTheFramesAskedFor) {
    JointSequence s(6, 2, 20.0);
    for (int f = 0; f < 6; ++f) s.at(f, 1) = Eigen::Vector3d(f, 0, 0);
    const JointSequence part = slice_frames(s, 2, 5);
    EXPECT_EQ(part.num_frames, 3);
    EXPECT_EQ(part.at(0, 1).x(), 2);
    EXPECT_EQ(part.at(2, 1).x(), 4);
    EXPECT_EQ(frames_of(0.26, 50.0), 13);
}

TEST(JointSequence, ConcatenatingTwoSlicesGivesTheWholeBack) {
    JointSequence s(6, 2, 20.0);
    for (int f = 0; f < 6; ++f) s.at(f, 1) = Eigen::Vector3d(f, -f, 2 * f);
    const JointSequence whole = concatenate_frames(slice_frames(s, 0, 2), slice_frames(s, 2, 6));
    ASSERT_EQ(whole.num_frames, 6);
    EXPECT_EQ(whole.positions, s.positions);
    // Another joint count or rate is refused, naming what differs.
    EXPECT_TRUE(
        test::contains(test::error_message([&] { concatenate_frames(s, JointSequence(2, 3, 20.0)); }), "3 joints"));
    EXPECT_TRUE(test::contains(test::error_message([&] { concatenate_frames(s, JointSequence(2, 2, 30.0)); }), "30.0"));
}

TEST(JointSequence, FrameRatesAboveZeroUpTo1000AreAccepted) {
    EXPECT_NO_THROW(check_motion_fps(20, "--fps"));
    EXPECT_NO_THROW(check_motion_fps(1000, "--fps"));
    for (const double bad : {0.0, -5.0, 1000.5, 1e12, std::nan(""), HUGE_VAL})
        EXPECT_EQ(test::error_message([&] { check_motion_fps(bad, "--fps"); }).rfind("--fps: frame rate", 0), 0u)
            << bad;
}
