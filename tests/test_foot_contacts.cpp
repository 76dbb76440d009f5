// Stance phases on feet whose motion is built frame by frame, so which frames are stance is known.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "motion/foot_contacts.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {
namespace {

using Eigen::Vector3d;
using namespace smpl22;

void place_foot(JointSequence& m, int f, int ankle, int toe, const Vector3d& ankle_at) {
    m.at(f, ankle) = ankle_at;
    m.at(f, toe) = ankle_at + Vector3d(0, -0.06, 0.13);
}

// 40 frames at 20 fps. Left foot: planted at z = 0 for frames 0-11, swinging 10 cm above its stance height at
// 2 m/s over frames 12-19, planted at z = 0.8 from frame 20. Right foot: planted throughout, except one frame
// (25) of capture jitter that throws it 5 cm sideways.
JointSequence two_feet() {
    JointSequence m(40, kNumJoints, kFps);
    for (int f = 0; f < 40; ++f) {
        for (int j = 0; j < kNumJoints; ++j) m.at(f, j) = Vector3d(0, 0.9, 0);
        const double z = f < 12 ? 0.0 : std::min(0.8, 0.1 * (f - 11));
        const double lift = f >= 12 && f < 20 ? 0.10 : 0.0;
        place_foot(m, f, left_ankle, left_foot, Vector3d(0.1, 0.08 + lift, z));
        place_foot(m, f, right_ankle, right_foot, Vector3d(f == 25 ? -0.15 : -0.1, 0.08, 0.3));
    }
    return m;
}

TEST(FootContacts, FindsEachStanceOfEachFoot) {
    const std::vector<StancePhase> phases = detect_stance_phases(two_feet());
    ASSERT_EQ(phases.size(), 3u);
    // Ordered by first frame, left before right at a tie. Frame 11 is the last still frame of the left foot,
    // but its central difference already sees the swing (1 m/s): stance ends at 10.
    EXPECT_EQ(phases[0].foot, Foot::left);
    EXPECT_EQ(phases[0].first_frame, 0);
    EXPECT_EQ(phases[0].last_frame, 10);
    EXPECT_EQ(phases[1].foot, Foot::right);
    EXPECT_EQ(phases[1].first_frame, 0);
    EXPECT_EQ(phases[1].last_frame, 39);  // the jitter's one-frame gaps (24 and 26, at 0.5 m/s) are closed
    EXPECT_EQ(phases[2].foot, Foot::left);
    EXPECT_EQ(phases[2].first_frame, 20);
    EXPECT_EQ(phases[2].last_frame, 39);
}

TEST(FootContacts, ALowSlowMomentShorterThanTheMinimumIsNoStance) {
    JointSequence m = two_feet();
    // The left foot pauses at its stance height in mid-swing for frames 14-17: by central difference only
    // 15 and 16 are still, two frames, under the minimum of three.
    for (int f = 14; f <= 17; ++f) place_foot(m, f, left_ankle, left_foot, Vector3d(0.1, 0.08, 0.35));
    const std::vector<bool> left = stance_frames(m, Foot::left);
    EXPECT_TRUE(left[15] && left[16] && !left[14] && !left[17]);
    const std::vector<StancePhase> phases = detect_stance_phases(m);
    for (const StancePhase& p : phases) {
        if (p.foot != Foot::left) continue;
        EXPECT_TRUE(p.last_frame <= 10 || p.first_frame >= 20) << p.first_frame << "-" << p.last_frame;
    }
}

TEST(FootContacts, TheMinimumStanceIsInSecondsAtAnyRate) {
    // At 60 fps: the left foot stands for 0.5 s, then pauses mid-swing for 0.1 s (4 still frames by central
    // difference: more than three frames, less than 0.15 s), then stands again from 1 s. Two frames in which the
    // planted right foot reads 6 cm high (1/30 s, under the 0.05 s gap bound) are closed.
    constexpr double fps = 60;
    JointSequence m(90, kNumJoints, fps);
    for (int f = 0; f < m.num_frames; ++f) {
        const double t = f / fps;
        for (int j = 0; j < kNumJoints; ++j) m.at(f, j) = Vector3d(0, 0.9, 0);
        const bool paused = f >= 42 && f<48, swinging = f> 30 && f < 60 && !paused;
        const double z = f <= 30 ? 0.0 : f < 42 ? 2 * (t - 0.5) : f < 48 ? 0.4 : f < 60 ? 0.4 + 2 * (t - 0.8) : 0.8;
        place_foot(m, f, left_ankle, left_foot, Vector3d(0.1, 0.08 + (swinging ? 0.10 : 0.0), z));
        place_foot(m, f, right_ankle, right_foot, Vector3d(-0.1, f == 40 || f == 41 ? 0.14 : 0.08, 0.3));
    }
    int left = 0;
    for (const StancePhase& p : detect_stance_phases(m)) {
        if (p.foot == Foot::right) {
            EXPECT_EQ(p.first_frame, 0);
            EXPECT_EQ(p.last_frame, 89);
            continue;
        }
        ++left;
        EXPECT_TRUE(p.last_frame <= 31 || p.first_frame >= 59)
            << p.first_frame << "-" << p.last_frame;  // not the pause
    }
    EXPECT_EQ(left, 2);
}

TEST(FootContacts, RefusesTooFewFrames) {
    EXPECT_THROW(detect_stance_phases(JointSequence(2, kNumJoints, kFps)), Error);
}

}  // namespace
}  // namespace t2imu
