// Measured captions say what the measurements say: the pace class at its thresholds, the turn's side, the
// direction of travel, the order of a stairs round trip and of sitting down and standing up; none for a tag the
// measurements contradict; the same captions for the same seed; and the attribute words a prompt asks for.
#include <gtest/gtest.h>

#include <algorithm>

#include "data/measured_captions.hpp"

using namespace t2imu;

namespace {

MotionAttributes walk(double speed) {
    MotionAttributes a;
    a.duration_s = 8, a.ground_speed_m_s = speed, a.distance_m = speed * 8, a.travel = TravelDirection::forward;
    a.cadence_steps_min = 110, a.stride_length_m = 2 * speed / (110 / 60.0);
    return a;
}

bool every_contains_one_of(const std::vector<std::string>& captions, const std::vector<std::string>& words) {
    return !captions.empty() && std::all_of(captions.begin(), captions.end(), [&](const std::string& c) {
        return std::any_of(words.begin(), words.end(),
                           [&](const std::string& w) { return c.find(w) != std::string::npos; });
    });
}

bool none_contains(const std::vector<std::string>& captions, const std::string& word) {
    return std::none_of(captions.begin(), captions.end(),
                        [&](const std::string& c) { return c.find(word) != std::string::npos; });
}

}  // namespace

TEST(MeasuredCaptions, PaceClassesChangeAtTheirThresholds) {
    EXPECT_EQ(walking_pace(0.99), WalkingPace::slow);
    EXPECT_EQ(walking_pace(1.0), WalkingPace::normal);
    EXPECT_EQ(walking_pace(1.5), WalkingPace::normal);
    EXPECT_EQ(walking_pace(1.51), WalkingPace::brisk);
    EXPECT_EQ(running_pace(2.69), RunningPace::jog);
    EXPECT_EQ(running_pace(3.5), RunningPace::run);
    EXPECT_EQ(running_pace(5.01), RunningPace::sprint);
    EXPECT_STREQ(walking_pace_name(WalkingPace::brisk), "brisk");
    EXPECT_STREQ(running_pace_name(RunningPace::jog), "jog");
}

TEST(MeasuredCaptions, TheActivityIsTheFirstDescribedTag) {
    EXPECT_EQ(caption_activity("walking;standing"), "walking");
    EXPECT_EQ(caption_activity("standing;sitting"), "sitting");
    EXPECT_EQ(caption_activity("dancing"), "");
    EXPECT_EQ(caption_activity(""), "");
}

TEST(MeasuredCaptions, ASlowWalkIsCaptionedSlowAndABriskOneFast) {
    const auto slow = measured_captions(walk(0.7), "walking", 5, 1);
    const auto brisk = measured_captions(walk(1.8), "walking", 5, 1);
    EXPECT_TRUE(every_contains_one_of(slow, {"slow", "stroll"}));
    EXPECT_TRUE(every_contains_one_of(brisk, {"quick", "brisk", "fast", "hurries"}));
    EXPECT_TRUE(none_contains(slow, "quick") && none_contains(slow, "fast"));
    EXPECT_TRUE(none_contains(brisk, "slow"));
    const auto jog = measured_captions(walk(2.2), "running", 5, 1),
               sprint = measured_captions(walk(6.0), "running", 5, 1);
    EXPECT_TRUE(every_contains_one_of(jog, {"jog", "slowly"}));
    EXPECT_TRUE(every_contains_one_of(sprint, {"sprint", "very fast"}));
}

// Running's pace words only in its tails: an easy jog (< 2.2 m/s) is slow, a fast run (> 3.3 m/s) fast, and the
// paces between (a 2.6 m/s jog, a 2.8 m/s run) name neither.
TEST(MeasuredCaptions, RunningPaceWordsNameOnlyTheTails) {
    for (uint64_t seed = 0; seed < 10; ++seed) {
        EXPECT_TRUE(every_contains_one_of(measured_captions(walk(2.0), "running", 3, seed), {"slow", "easy"}));
        EXPECT_TRUE(every_contains_one_of(measured_captions(walk(3.6), "running", 3, seed), {"fast", "quickly"}));
        for (double v : {2.6, 2.8}) {
            const auto middle = measured_captions(walk(v), "running", 3, seed);
            ASSERT_FALSE(middle.empty());
            EXPECT_TRUE(none_contains(middle, "slow") && none_contains(middle, "easy") &&
                        none_contains(middle, "fast") && none_contains(middle, "quick"));
        }
    }
}

TEST(MeasuredCaptions, TurnsAndTravelNameTheirSide) {
    MotionAttributes a = walk(1.2);
    a.heading_change_deg = a.path_turn_deg = 90;
    int left = 0;
    for (uint64_t seed = 0; seed < 20; ++seed) {
        const auto c = measured_captions(a, "walking", 1, seed);
        ASSERT_EQ(c.size(), 1u);
        EXPECT_EQ(c[0].find("right"), std::string::npos) << c[0];
        left += c[0].find("left") != std::string::npos;
    }
    EXPECT_GE(left, 10);  // the turn is mentioned in most captions (a random subset of attributes each)
    a.heading_change_deg = a.path_turn_deg = 0;
    a.travel = TravelDirection::backward;
    EXPECT_TRUE(every_contains_one_of(measured_captions(a, "walking", 4, 3), {"backward"}));
    a.travel = TravelDirection::right;
    EXPECT_TRUE(every_contains_one_of(measured_captions(a, "walking", 4, 3), {"right"}));
}

TEST(MeasuredCaptions, SequencesKeepTheirOrder) {
    MotionAttributes stairs;
    stairs.steps_up = 6, stairs.steps_down = 6, stairs.transitions = {Transition::climb_up, Transition::climb_down};
    EXPECT_TRUE(
        every_contains_one_of(measured_captions(stairs, "stairs", 3, 2),
                              {"up the stairs and then", "up a flight of stairs and then", "up the stairs, turns"}));
    MotionAttributes sit;
    sit.seated_s = 3, sit.transitions = {Transition::sit_down, Transition::stand_up};
    EXPECT_TRUE(every_contains_one_of(measured_captions(sit, "sitting", 3, 2),
                                      {"stands up again", "stands back up", "then gets up"}));
    MotionAttributes lie;
    lie.lying_s = 4, lie.lying_side = LyingSide::left, lie.transitions = {Transition::lie_down};
    EXPECT_TRUE(every_contains_one_of(measured_captions(lie, "lying", 3, 2), {"left side"}));
}

TEST(MeasuredCaptions, NoneWhereTheMeasurementsContradictTheTag) {
    EXPECT_TRUE(measured_captions(walk(0.1), "walking", 3, 1).empty());
    EXPECT_TRUE(measured_captions(walk(0.5), "running", 3, 1).empty());
    EXPECT_TRUE(measured_captions(walk(1.0), "stairs", 3, 1).empty());  // no steps
    EXPECT_TRUE(measured_captions(walk(1.0), "dancing", 3, 1).empty());
    EXPECT_TRUE(measured_captions(walk(1.0), "walking", 0, 1).empty());
}

TEST(MeasuredCaptions, TheSameSeedGivesTheSameDistinctCaptions) {
    const auto a = measured_captions(walk(1.2), "walking", 4, 7), b = measured_captions(walk(1.2), "walking", 4, 7);
    EXPECT_EQ(a, b);
    std::vector<std::string> sorted = a;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::unique(sorted.begin(), sorted.end()), sorted.end());
    for (const std::string& c : a) EXPECT_EQ(c.back(), '.');
}

TEST(MeasuredCaptions, APromptAsksForTheAttributesItsWordsName) {
    const auto asked = attributes_asked("A person walks SLOWLY and then turns left.");
    EXPECT_NE(std::find(asked.begin(), asked.end(), "pace_slow"), asked.end());
    EXPECT_NE(std::find(asked.begin(), asked.end(), "turn_left"), asked.end());
    EXPECT_NE(std::find(asked.begin(), asked.end(), "sequence"), asked.end());
    EXPECT_EQ(std::find(asked.begin(), asked.end(), "turn_right"), asked.end());
    EXPECT_TRUE(attributes_asked("a person walks").empty());
}
