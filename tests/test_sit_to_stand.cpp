// Sitting down and standing up derived from a procedural idle stand (HumanML3D's target skeleton) whose
// heights are known, and from a captured idle stand when the shared mocap is at hand.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "motion/mocap_import.hpp"
#include "motion/motion_edit.hpp"
#include "motion/motion_quality.hpp"
#include "motion/sit_to_stand.hpp"
#include "motion/skeleton.hpp"
#include "motion/two_bone_ik.hpp"
#include "test_util.hpp"

namespace t2imu {
namespace {

using Eigen::Vector3d;
using namespace smpl22;

constexpr double kStandPelvisHeight = 0.88;  // both legs reach the floor with the knees bent (right leg 0.816 m)

// Standing still facing +Z, feet flat (ankles 8 cm, toes 2 cm above the floor), knees slightly bent, the body
// swaying 1 cm sideways every 4 s and the trunk 2 deg forward and back every 3 s: idle standing.
JointSequence procedural_stand(int frames) {
    JointSequence m(frames, kNumJoints, kFps);
    for (int f = 0; f < frames; ++f) {
        const double t = f / kFps;
        m.at(f, pelvis) = Vector3d(0.01 * std::sin(2 * test::kPi * t / 4), kStandPelvisHeight, 0);
        for (int j = 1; j < kNumJoints; ++j)
            if (!is_leg_joint(j))
                m.at(f, j) = m.at(f, kParents[static_cast<size_t>(j)]) + kTargetOffsets[static_cast<size_t>(j)];
        flex_trunk(m, f, Vector3d::UnitZ(), 0.035 * std::sin(2 * test::kPi * t / 3));
        for (const LegJoints& leg : kLegs) {
            const double foot = kTargetOffsets[static_cast<size_t>(leg.toe)].norm();
            m.at(f, leg.ankle) = Vector3d(kTargetOffsets[static_cast<size_t>(leg.hip)].x(), 0.08, 0);
            m.at(f, leg.toe) = m.at(f, leg.ankle) + Vector3d(0, -0.06, std::sqrt(foot * foot - 0.06 * 0.06));
            m.at(f, leg.knee) = solve_two_bone_ik(m.at(f, leg.hip), m.at(f, leg.ankle),
                                                  kTargetOffsets[static_cast<size_t>(leg.knee)].norm(),
                                                  kTargetOffsets[static_cast<size_t>(leg.ankle)].norm(),
                                                  m.at(f, leg.hip) + Vector3d(0, -0.4, 1))
                                    .middle;
        }
    }
    return m;
}

// Frames of each phase at 20 fps with the default options: 20 standing, 44 down, 60 seated, 36 up, 20 standing.
constexpr int kSeatedFrom = 64, kUpFrom = 124;

TEST(SitToStand, TheProceduralStandIsAValidSource) {
    const JointSequence stand = procedural_stand(200);
    EXPECT_LT(max_bone_length_error(stand, bone_lengths(stand, 0)), 1e-9);
    EXPECT_EQ(stand_sit_stand_frames(ChairOptions{}, kFps), 181);
}

TEST(SitToStand, TheFeetStayPlanted) {
    const JointSequence m = stand_sit_stand(procedural_stand(200), ChairOptions{});
    for (int f = 0; f < m.num_frames; ++f)
        for (const LegJoints& leg : kLegs) {
            EXPECT_LT((m.at(f, leg.ankle) - m.at(0, leg.ankle)).norm(), 0.01) << "frame " << f;
            EXPECT_LT((m.at(f, leg.toe) - m.at(0, leg.toe)).norm(), 0.01) << "frame " << f;
        }
}

TEST(SitToStand, SeatedThePelvisRestsOnTheSeatWithTheKneesAtARightAngle) {
    for (double seat : {0.40, 0.45, 0.50}) {
        ChairOptions o;
        o.seat_height_m = seat;
        const JointSequence m = stand_sit_stand(procedural_stand(200), o);
        for (int f = kSeatedFrom; f < kUpFrom; ++f) {
            EXPECT_NEAR(m.at(f, pelvis).y(), seat + o.pelvis_above_seat_m, 1e-9) << "frame " << f;
            // Each knee about straight above its ankle (the chair is placed for the mean leg) with the thigh at
            // its length: flexion 90 deg less the thigh's slope down to the knee, which the seat height sets.
            for (int leg = 0; leg < 2; ++leg) {
                const LegJoints& l = kLegs[static_cast<size_t>(leg)];
                const double knee_height = 0.08 + kTargetOffsets[static_cast<size_t>(l.ankle)].norm();
                const double slope =
                    std::asin((m.at(f, l.hip).y() - knee_height) / kTargetOffsets[static_cast<size_t>(l.knee)].norm());
                EXPECT_NEAR(knee_flexion_rad(m, f, leg), test::kPi / 2 - slope, 0.05) << "seat " << seat;
            }
        }
        // The chair is behind: the seated pelvis sits well back from the standing one.
        EXPECT_LT(m.at(kSeatedFrom, pelvis).z(), m.at(0, pelvis).z() - 0.25);
    }
}

TEST(SitToStand, StartsAndEndsStandingAtTheSourcesHeight) {
    const JointSequence stand = procedural_stand(200);
    const JointSequence m = stand_sit_stand(stand, ChairOptions{});
    const int last = m.num_frames - 1;
    EXPECT_NEAR((m.at(0, pelvis) - stand.at(0, pelvis)).norm(), 0.0, 1e-3);
    EXPECT_NEAR((m.at(last, pelvis) - stand.at(last, pelvis)).norm(), 0.0, 1e-3);
    EXPECT_NEAR((m.at(last, head) - stand.at(last, head)).norm(), 0.0, 1e-3);
}

TEST(SitToStand, BonesKeepTheirLengthsAndNothingGoesThroughTheFloor) {
    const JointSequence stand = procedural_stand(200);
    const JointSequence m = stand_sit_stand(stand, ChairOptions{});
    EXPECT_LT(max_bone_length_error(m, bone_lengths(stand, 0)), 1e-6);
    const MotionQuality q = score_motion(m);
    EXPECT_DOUBLE_EQ(q.penetration_m, 0.0);
    EXPECT_TRUE(quality_failures(q, default_quality_thresholds()).empty());
    EXPECT_LT(q.pelvis_acc_m_s2, 5.0);  // a sweep over seconds, not a drop
}

TEST(SitToStand, TheTrunkBendsForwardToItsPeakOnTheWayDownAndUp) {
    ChairOptions o;
    o.trunk_flexion_peak_rad = 0.7;
    const JointSequence stand = procedural_stand(200);
    const JointSequence m = stand_sit_stand(stand, o);
    auto lean = [](const JointSequence& s, int f) {  // pelvis -> spine3 forward of vertical (rad)
        const Vector3d v = s.at(f, spine3) - s.at(f, pelvis);
        return std::atan2(v.z(), v.y());
    };
    double down_peak = 0, up_peak = 0;
    int up_peak_frame = 0;
    for (int f = 20; f < kSeatedFrom; ++f) down_peak = std::max(down_peak, lean(m, f) - lean(stand, f));
    for (int f = kUpFrom; f < kUpFrom + 36; ++f)
        if (lean(m, f) - lean(stand, f) > up_peak) up_peak = lean(m, f) - lean(stand, f), up_peak_frame = f;
    EXPECT_NEAR(down_peak, 0.7, 0.02);
    EXPECT_NEAR(up_peak, 0.7, 0.02);
    // Rising: the peak comes at seat-off, about a third into the movement, before the pelvis leaves the seat.
    EXPECT_NEAR(up_peak_frame - kUpFrom, 0.35 * 36, 1.0);
    EXPECT_NEAR(m.at(up_peak_frame, pelvis).y(), 0.45 + 0.10, 0.01);
    // Seated, the trunk is upright again and keeps the source's sway.
    EXPECT_NEAR(lean(m, 90), lean(stand, 90), 1e-9);
}

// The pace knob the dataset builder turns (data/derived_clips.hpp): every move is a minimum-jerk blend, so taking
// k times as long lowers the pelvis's vertical acceleration by k^2 (the reach limit's fixed 0.4 s envelope bends
// the last of the rise, hence the tolerance).
TEST(SitToStand, ASlowerPaceLowersThePelvisAccelerationByItsSquare) {
    auto peak_vertical_acceleration = [](const JointSequence& m, double from_s, double to_s) {  // m/s^2
        double peak = 0;
        for (int f = std::max(1, frames_of(from_s, m.fps)); f < std::min(m.num_frames - 1, frames_of(to_s, m.fps)); ++f)
            peak =
                std::max(peak, std::abs(m.at(f + 1, pelvis).y() - 2 * m.at(f, pelvis).y() + m.at(f - 1, pelvis).y()) *
                                   m.fps * m.fps);
        return peak;
    };
    ChairOptions natural, slow;
    slow.sit_down_s = 1.3 * natural.sit_down_s;
    slow.stand_up_s = 1.3 * natural.stand_up_s;
    slow.seated_s = 1.0;
    const JointSequence a = stand_sit_stand(procedural_stand(200), natural),
                        b = stand_sit_stand(procedural_stand(200), slow);
    const double down_a = peak_vertical_acceleration(a, 1.0, 3.2),
                 down_b = peak_vertical_acceleration(b, 1.0, 1.0 + slow.sit_down_s);
    const double up_from_a = 6.2, up_from_b = 1.0 + slow.sit_down_s + 1.0;
    const double up_a = peak_vertical_acceleration(a, up_from_a, up_from_a + 1.8),
                 up_b = peak_vertical_acceleration(b, up_from_b, up_from_b + slow.stand_up_s);
    EXPECT_GT(down_a, 0.5);
    EXPECT_GT(up_a, 0.5);
    EXPECT_NEAR(down_a / down_b, 1.69, 0.2);
    EXPECT_NEAR(up_a / up_b, 1.69, 0.2);
}

TEST(SitToStand, RefusesBadOptionsAndShortSourcesNamingTheField) {
    ChairOptions o;
    o.seat_height_m = 0.70;
    try {
        stand_sit_stand(procedural_stand(200), o);
        FAIL() << "accepted a 0.70 m seat";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("seat_height_m"), std::string::npos) << e.what();
    }
    EXPECT_THROW(stand_sit_stand(procedural_stand(100), ChairOptions{}), Error);
    // A source that steps 0.3 m to the side halfway: the planted feet would be left behind.
    JointSequence stepping = procedural_stand(200);
    for (int f = 100; f < stepping.num_frames; ++f)
        for (int j = 0; j < kNumJoints; ++j) stepping.at(f, j).x() += 0.3 * std::min(1.0, (f - 100) / 10.0);
    try {
        stand_sit_stand(stepping, ChairOptions{});
        FAIL() << "accepted a source that steps away";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("at frame 109"), std::string::npos) << e.what();
    }
    stepping = procedural_stand(200);
    for (int f = 0; f < stepping.num_frames; ++f)
        for (int j = 0; j < kNumJoints; ++j) stepping.at(f, j).x() += 0.2 * f / 200.0;  // 0.18 m: a weight shift
    EXPECT_NO_THROW(stand_sit_stand(stepping, ChairOptions{}));
}

TEST(SitToStand, ACapturedIdleStandSitsDown) {
    const std::string dir = test::unpacked_shared_archive("mocap/reactidle_bvh.tar.xz");
    if (dir.empty()) GTEST_SKIP() << "shared data not found: mocap/reactidle_bvh.tar.xz";
    JointSequence stand;
    try {
        stand = import_motion(dir + "/reactidle_bvh/008_acted.bvh");
    } catch (const Error& e) {
        // The ReActIdle skeleton (reactidle_rigify) is new to the importer; without it there is nothing to test.
        if (std::string(e.what()).find("known skeleton flavour") == std::string::npos) throw;
        GTEST_SKIP() << "the importer does not know the ReActIdle skeleton yet: " << e.what();
    }
    place_on_floor(stand);
    const JointSequence m = stand_sit_stand(stand, ChairOptions{});
    const MotionQuality q = score_motion(m);
    double ankle_move = 0, seated_knee = 0;
    for (int f = 0; f < m.num_frames; ++f)
        for (int leg = 0; leg < 2; ++leg)
            ankle_move = std::max(ankle_move, (m.at(f, kLegs[static_cast<size_t>(leg)].ankle) -
                                               m.at(0, kLegs[static_cast<size_t>(leg)].ankle))
                                                  .norm());
    for (int leg = 0; leg < 2; ++leg) seated_knee += 0.5 * knee_flexion_rad(m, 90, leg);
    std::printf(
        "[captured sit] frames %d, seated pelvis %.3f m, seated knee %.0f deg, ankle moved %.4f m, skate %.2f, "
        "penetration %.3f, "
        "hover %.3f, max acc %.0f, pelvis acc %.1f\n",
        m.num_frames, m.at(90, pelvis).y(), seated_knee * 180 / test::kPi, ankle_move, q.foot_skate_m_s,
        q.penetration_m, q.hover_m, q.max_acc_m_s2, q.pelvis_acc_m_s2);
    // The importer keeps ReActIdle's bones rigid (only the root's position channels count), and so does the edit.
    EXPECT_LT(max_bone_length_error(m, bone_lengths(stand, 0)), 1e-6);
    EXPECT_LT(ankle_move, 0.01);
    EXPECT_NEAR(m.at(90, pelvis).y(), 0.55, 1e-9);
    EXPECT_TRUE(quality_failures(q, default_quality_thresholds()).empty());
}

}  // namespace
}  // namespace t2imu
