// Derived clips from shared captured recordings: stairs (a flight, and a round trip) from a forward walk, sitting from
// idle standing; what cannot be a source gives nothing; the draw is the same every time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "data/derived_clips.hpp"
#include "data/hml3d_dataset.hpp"
#include "motion/foot_contacts.hpp"
#include "motion/mocap_import.hpp"
#include "motion/motion_attributes.hpp"
#include "motion/motion_edit.hpp"
#include "motion/motion_quality.hpp"
#include "motion/skeleton.hpp"
#include "test_util.hpp"

namespace t2imu {
namespace {

constexpr const char* kWalk = "bandai_bvh/dataset-2_walk_normal_001.bvh";  // forward walk
constexpr const char* kWalkBack = "bandai_bvh/dataset-1_walk-back_active_001.bvh";
constexpr const char* kIdle = "reactidle_bvh/000_genuine.bvh";
constexpr const char* kLieDown = "hdm05_amc/HDM_bd_lieDownFloor_001_120.amc";
constexpr const char* kHop = "hdm05_amc/HDM_bk_hopBothLegs1hops_013_120.amc";

JointSequence shared_clip(const std::string& archive, const std::string& file) {
    const std::string root = test::unpacked_shared_archive(archive);
    return root.empty() ? JointSequence() : import_motion(root + "/" + file);
}

// Largest change of any bone's length from its length at frame 0 (m).
double max_bone_change(const JointSequence& m) { return max_bone_length_error(m, bone_lengths(m, 0)); }

TEST(DerivedClips, AForwardWalkGivesAFlightOfStairsAndOnRequestARoundTrip) {
    std::string archive;
    SHARED_OR_SKIP(archive, "mocap/bandai_bvh_native.tar.xz");
    const JointSequence walk = shared_clip("mocap/bandai_bvh_native.tar.xz", kWalk);
    DeriveReport report;
    ASSERT_EQ(derive_clips(walk, "walking", kWalk, report).size(), 1u) << "refused " << report.refused;  // the flight
    DeriveOptions trips;
    trips.stairs_round_trips = true;
    trips.turning_walks = true;
    const std::vector<DerivedClip> clips = derive_clips(walk, "walking", kWalk, report, trips);
    // This walk is one of every other that also gives a round trip on request, and every forward walk a turn.
    ASSERT_EQ(clips.size(), 3u) << "refused " << report.refused << ", failed quality " << report.failed_quality;
    const DerivedClip& c = clips[0];
    EXPECT_TRUE(c.method == "stairs_up" || c.method == "stairs_down");
    EXPECT_EQ(c.activity, c.method);
    EXPECT_GE(c.parameters["rise_m"].get<double>(), 0.15);
    EXPECT_LE(c.parameters["rise_m"].get<double>(), 0.19);
    EXPECT_GE(c.parameters["going_m"].get<double>(), 0.25);
    EXPECT_LE(c.parameters["going_m"].get<double>(), 0.32);
    EXPECT_EQ(c.captions.size(), 3u);
    // The body climbs (or descends) the flight: its pelvis ends steps * rise higher (lower) within 5 cm.
    const double climb = c.joints.at(c.joints.num_frames - 1, 0).y() - c.joints.at(0, 0).y();
    const double flight = c.parameters["steps"].get<int>() * c.parameters["rise_m"].get<double>();
    EXPECT_GT(std::fabs(climb), 0.5 * flight);
    EXPECT_EQ(climb > 0, c.method == "stairs_up");
    EXPECT_LT(max_bone_change(c.joints), 1e-6);
    // The same recording gives the same clips.
    DeriveReport again;
    const std::vector<DerivedClip> redrawn = derive_clips(walk, "walking", kWalk, again, trips);
    EXPECT_EQ(redrawn[0].joints.positions, c.joints.positions);
    EXPECT_EQ(redrawn[1].joints.positions, clips[1].joints.positions);

    // The round trip climbs a flight and comes down the next: its pelvis rises at least two steps above where it
    // starts and falls at least two below its top by the end, over the length drawn; at 20 fps it is a clip the
    // training keeps, passing quality.
    const DerivedClip& trip = clips[1];
    EXPECT_EQ(trip.method, "stairs_round_trip");
    EXPECT_EQ(trip.activity, "stairs");  // either direction: not under stairs_down alone, where it drew climbs
    EXPECT_EQ(trip.captions.size(), 3u);
    double top = -1e9;
    for (int f = 0; f < trip.joints.num_frames; ++f) top = std::max(top, trip.joints.at(f, 0).y());
    const double two_steps = 2 * trip.parameters.at("rise_m").get<double>();
    EXPECT_GT(top - trip.joints.at(0, 0).y(), two_steps);
    EXPECT_GT(top - trip.joints.at(trip.joints.num_frames - 1, 0).y(), two_steps);
    const double seconds = trip.parameters.at("seconds").get<double>();
    EXPECT_GE(seconds, kRoundTripMinSeconds);
    EXPECT_LE(seconds, kRoundTripMaxSeconds);
    EXPECT_LE(trip.joints.num_frames, frames_of(seconds, walk.fps));
    EXPECT_TRUE(Hml3dDataset::usable_length(trip.joints_20fps.num_frames)) << trip.joints_20fps.num_frames << " frames";
    JointSequence scored = trip.joints_20fps;
    place_on_floor(scored);
    EXPECT_TRUE(quality_failures(score_motion(scored), default_quality_thresholds()).empty());
    EXPECT_LT(max_bone_change(trip.joints), 1e-6);

    // The turned walk is measured turning the way and about as far as drawn, and its captions name that side.
    const DerivedClip& turn = clips[2];
    EXPECT_EQ(turn.method, "walk_turn");
    EXPECT_EQ(turn.activity, "walking");
    const double drawn = turn.parameters["turn_rad"].get<double>() * 180 / M_PI,
                 measured = measure_attributes(turn.joints_20fps).heading_change_deg;
    EXPECT_GE(std::fabs(drawn), 60);
    EXPECT_NEAR(measured, drawn, 15);  // the captured walk's own sway on top of the turn
    const std::string side = std::fabs(drawn) >= 135 ? "around" : drawn > 0 ? "left" : "right";
    for (const std::string& caption : turn.captions) EXPECT_NE(caption.find(side), std::string::npos) << caption;
    EXPECT_LT(max_bone_change(turn.joints), 1e-6);
    EXPECT_EQ(redrawn[2].joints.positions, turn.joints.positions);
}

TEST(DerivedClips, BackwardWalksAndMixedRecordingsGiveNothing) {
    std::string archive;
    SHARED_OR_SKIP(archive, "mocap/bandai_bvh_native.tar.xz");
    DeriveReport report;
    DeriveOptions turns;  // a backward walk is not turned either: "walks forward and turns" would not say what it does
    turns.turning_walks = true;
    EXPECT_TRUE(
        derive_clips(shared_clip("mocap/bandai_bvh_native.tar.xz", kWalkBack), "walking", kWalkBack, report, turns)
            .empty());
    EXPECT_EQ(report.refused, 2);  // the staircase and the turn
    const JointSequence walk = shared_clip("mocap/bandai_bvh_native.tar.xz", kWalk);
    EXPECT_TRUE(derive_clips(walk, "walking;dancing", kWalk, report).empty());  // not one activity: not a source
    EXPECT_TRUE(derive_clips(walk, "running", kWalk, report).empty());
}

TEST(DerivedClips, IdleStandingGivesSitDownStandUpClipsThatPassTheQualityThresholds) {
    std::string archive;
    SHARED_OR_SKIP(archive, "mocap/reactidle_bvh.tar.xz");
    const JointSequence idle = shared_clip("mocap/reactidle_bvh.tar.xz", kIdle);
    DeriveReport report;
    const std::vector<DerivedClip> clips = derive_clips(idle, "standing", kIdle, report);
    EXPECT_EQ(static_cast<int>(clips.size()) + report.refused + report.failed_quality, kSitsPerRecording);
    ASSERT_GE(clips.size(), 4u);
    for (const DerivedClip& c : clips) {
        EXPECT_EQ(c.activity, "sitting");
        EXPECT_LE(c.joints.num_frames, 9.4 * 20 + 1);  // one training clip, however slow the pace
        // The pace scales both movements; the still phases make room for a slow one.
        const double pace = c.parameters["pace_factor"].get<double>();
        EXPECT_GE(pace, kSitPaceFactorMin);
        EXPECT_LE(pace, kSitPaceFactorMax);
        EXPECT_GE(c.parameters["sit_down_s"].get<double>() / pace, 1.8 - 1e-9);
        EXPECT_LE(c.parameters["sit_down_s"].get<double>() / pace, 2.4 + 1e-9);
        EXPECT_GE(c.parameters["stand_up_s"].get<double>() / pace, 1.5 - 1e-9);
        EXPECT_LE(c.parameters["stand_up_s"].get<double>() / pace, 2.0 + 1e-9);
        EXPECT_TRUE(quality_failures(score_motion(c.joints), default_quality_thresholds()).empty());
        EXPECT_LT(max_bone_change(c.joints), 1e-6);
        // Seated, the pelvis rests pelvis_above_seat_m above the seat, which is about half the hip height.
        double lowest = 1e9, floor = 1e9;
        for (int f = 0; f < c.joints.num_frames; ++f) {
            lowest = std::min(lowest, c.joints.at(f, 0).y());
            for (int j : {smpl22::left_foot, smpl22::right_foot}) floor = std::min(floor, c.joints.at(f, j).y());
        }
        const double seat = c.parameters["seat_height_m"].get<double>();
        EXPECT_NEAR(lowest - floor, seat + c.parameters["pelvis_above_seat_m"].get<double>(), 0.03);
        const double hip = 0.5 * (idle.at(0, smpl22::left_hip).y() + idle.at(0, smpl22::right_hip).y()) - floor;
        EXPECT_GE(seat, 0.45 * hip);
        EXPECT_LE(seat, 0.59 * hip);
    }
}

TEST(DerivedClips, ALieDownClipGivesLyingStillAndTurningClips) {
    std::string archive;
    SHARED_OR_SKIP(archive, "mocap/hdm05_amc_native.tar.xz");
    const JointSequence lie = shared_clip("mocap/hdm05_amc_native.tar.xz", kLieDown);
    DeriveReport report;
    // By default the still clips only; the turns on request.
    std::vector<DerivedClip> clips = derive_clips(lie, "lying", kLieDown, report);
    ASSERT_EQ(static_cast<int>(clips.size()), kLyingPerRecording);
    for (const DerivedClip& c : clips) EXPECT_EQ(c.method, "lying_still");
    DeriveOptions with_turns;
    with_turns.lying_turns = true;
    clips = derive_clips(lie, "lying", kLieDown, report, with_turns);
    ASSERT_EQ(static_cast<int>(clips.size()), kLyingPerRecording + kLyingTurnsPerRecording);
    const Eigen::Vector3d end = lie.at(lie.num_frames - 1, 0);
    int still = 0, turns = 0, left = 0;
    for (const DerivedClip& c : clips) {
        EXPECT_EQ(c.activity, "lying");
        EXPECT_TRUE(quality_failures(score_motion(c.joints), default_quality_thresholds()).empty());
        EXPECT_LT(max_bone_change(c.joints), 1e-6);
        EXPECT_LE(c.joints.num_frames, 9.4 * 20 + 1);  // one training clip
        if (c.method == "lying_still") {
            ++still;
            // Still: the pelvis stays where the captured clip left it, within breathing's millimetres.
            for (int f = 0; f < c.joints.num_frames; ++f) EXPECT_LT((c.joints.at(f, 0) - end).norm(), 0.01);
            continue;
        }
        ASSERT_EQ(c.method, "lying_turn");
        ++turns;
        left += c.parameters["angle_rad"].get<double>() > 0;
        // It starts and ends lying where the captured clip left it, and turns by its angle in between.
        EXPECT_LT((c.joints.at(0, 0) - end).norm(), 0.01);
        EXPECT_LT((c.joints.at(c.joints.num_frames - 1, 0) - end).norm(), 0.01);
        const Eigen::Vector3d across0 = c.joints.at(0, smpl22::left_hip) - c.joints.at(0, smpl22::right_hip);
        double most = 0;
        for (int f = 0; f < c.joints.num_frames; ++f) {
            const Eigen::Vector3d across = c.joints.at(f, smpl22::left_hip) - c.joints.at(f, smpl22::right_hip);
            most = std::max(most, std::acos(std::clamp(across0.normalized().dot(across.normalized()), -1.0, 1.0)));
        }
        EXPECT_NEAR(most, std::abs(c.parameters["angle_rad"].get<double>()), 0.02);  // breathing does not turn the hips
    }
    EXPECT_EQ(still, kLyingPerRecording);
    EXPECT_EQ(turns, kLyingTurnsPerRecording);
    EXPECT_EQ(left, 1);  // one onto each side
    // On request, the lie-down followed by rest: the captured frames first, then the end pose held, breathing.
    DeriveOptions with_rest;
    with_rest.lie_down_rests = true;
    clips = derive_clips(lie, "lying", kLieDown, report, with_rest);
    ASSERT_EQ(static_cast<int>(clips.size()), kLyingPerRecording + 1);
    const DerivedClip& rest = clips.back();
    ASSERT_EQ(rest.method, "lie_down_rest");
    EXPECT_EQ(rest.activity, "lying");
    const double rest_s = rest.parameters["rest_seconds"].get<double>();
    EXPECT_GE(rest_s, kLieDownRestMinSeconds);
    EXPECT_LE(rest_s, kLieDownRestMaxSeconds);
    EXPECT_EQ(rest.joints.num_frames, lie.num_frames + frames_of(rest_s, lie.fps));
    EXPECT_LE(rest.joints.num_frames, kLieDownRestMaxClipSeconds * lie.fps + 1);
    for (int f = 0; f < lie.num_frames; ++f) EXPECT_EQ((rest.joints.at(f, 0) - lie.at(f, 0)).norm(), 0.0);
    for (int f = lie.num_frames; f < rest.joints.num_frames; ++f) EXPECT_LT((rest.joints.at(f, 0) - end).norm(), 0.01);
    EXPECT_TRUE(quality_failures(score_motion(rest.joints), default_quality_thresholds()).empty());
    // Its captions are its own, not the still clips' (the caption anchor blends the captions of an activity).
    for (const std::string& caption : rest.captions) {
        EXPECT_TRUE(test::contains(caption, "lies")) << caption;
        for (int k = 0; k < kLyingPerRecording; ++k)
            EXPECT_EQ(std::count(clips[k].captions.begin(), clips[k].captions.end(), caption), 0) << caption;
    }
    // A standing recording does not end lying: it gives no lying clip.
    EXPECT_TRUE(derive_clips(shared_clip("mocap/bandai_bvh_native.tar.xz", kWalk), "lying", kWalk, report).empty());
}

// Highest minus lowest pelvis height over the clip (m).
double pelvis_height_range(const JointSequence& m) {
    double lo = 1e9, hi = -1e9;
    for (int f = 0; f < m.num_frames; ++f) lo = std::min(lo, m.at(f, 0).y()), hi = std::max(hi, m.at(f, 0).y());
    return hi - lo;
}

TEST(DerivedClips, ACapturedJumpGivesOneJumpOfAnotherHeightAndAShortOneASeries) {
    std::string archive;
    SHARED_OR_SKIP(archive, "mocap/hdm05_amc_native.tar.xz");
    const JointSequence hop = shared_clip("mocap/hdm05_amc_native.tar.xz", kHop);
    ASSERT_LT(hop.num_frames / hop.fps, 2.0);  // one hop: shorter than the training keeps
    DeriveReport report;
    const std::vector<DerivedClip> clips = derive_clips(hop, "jumping", kHop, report);
    ASSERT_EQ(clips.size(), 2u) << "refused " << report.refused << ", failed quality " << report.failed_quality;
    const DerivedClip& c = clips[0];
    EXPECT_EQ(c.method, "jump_rescaled");
    EXPECT_EQ(c.activity, "jumping");
    const double k = c.parameters["time_scale"].get<double>();
    EXPECT_TRUE((k >= 0.88 && k <= 0.95) || (k >= 1.05 && k <= 1.12)) << k;
    EXPECT_DOUBLE_EQ(c.parameters["height_scale"].get<double>(), k * k);
    EXPECT_NEAR(c.joints.num_frames, k * (hop.num_frames - 1) + 1, 1.0);
    // Every vertical excursion of the body is k^2 as large: the crouch and the flight (5 %: resampling at 20 fps).
    EXPECT_NEAR(pelvis_height_range(c.joints) / pelvis_height_range(hop), k * k, 0.05 * k * k);
    EXPECT_TRUE(quality_failures(score_motion(c.joints), default_quality_thresholds()).empty());
    EXPECT_LT(max_bone_change(c.joints), 1e-6);
    EXPECT_EQ(c.captions.size(), 3u);

    // The series: kJumpsPerSeriesMin-Max rescaled hops in a row, long enough to train on, as many flights.
    const DerivedClip& series = clips[1];
    EXPECT_EQ(series.method, "jump_series");
    EXPECT_EQ(series.activity, "jumping");
    const int jumps = series.parameters["jumps"].get<int>();
    EXPECT_GE(jumps, kJumpsPerSeriesMin);
    EXPECT_LE(jumps, kJumpsPerSeriesMax);
    ASSERT_EQ(series.parameters["time_scales"].size(), static_cast<size_t>(jumps));
    EXPECT_GE(series.joints_20fps.num_frames, Hml3dDataset::kMinFrames);
    EXPECT_LT(series.joints_20fps.num_frames, Hml3dDataset::kMaxFramesExclusive);
    const std::vector<bool> left = stance_frames(series.joints, Foot::left),
                            right = stance_frames(series.joints, Foot::right);
    int flights = 0;
    for (int f = 1; f < series.joints.num_frames; ++f)
        flights += !left[static_cast<size_t>(f)] && !right[static_cast<size_t>(f)] &&
                   (left[static_cast<size_t>(f - 1)] || right[static_cast<size_t>(f - 1)]);
    EXPECT_EQ(flights, jumps);
    EXPECT_TRUE(quality_failures(score_motion(series.joints_20fps), default_quality_thresholds()).empty());
    EXPECT_LT(max_bone_change(series.joints), 1e-6);
    EXPECT_EQ(series.captions.size(), 3u);
}

}  // namespace
}  // namespace t2imu
