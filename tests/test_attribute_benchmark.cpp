// The attribute benchmark on draws whose answers are known: the speed ratio of fast over slow prompts, turns in
// and against the asked direction, backward travel, a stairs round trip's rise and fall of the pelvis, and the
// order of sitting down and standing up; and a synth folder without kept motions refused.
#include <gtest/gtest.h>

#include <filesystem>

#include "analysis/attribute_benchmark.hpp"
#include "core/error.hpp"
#include "motion/skeleton.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

AttributeDraw draw(const std::string& activity, const std::string& prompt, double speed, double heading = 0) {
    AttributeDraw d;
    d.activity = activity, d.prompt = prompt;
    d.attributes.ground_speed_m_s = speed, d.attributes.heading_change_deg = heading;
    return d;
}

// Every joint at height offset(f) above a standing pose's, 20 fps.
template <class Height>
JointSequence lifted(int frames, Height height) {
    JointSequence m(frames, 22, 20.0);
    for (int f = 0; f < frames; ++f)
        for (int k = 0; k < 22; ++k) m.at(f, k) = Eigen::Vector3d(0.1 * (k % 3), 0.05 + 0.07 * k + height(f), 0);
    return m;
}

}  // namespace

TEST(AttributeBenchmark, TheSpeedRatioIsTheFastMedianOverTheSlowMedian) {
    std::vector<AttributeDraw> d = {draw("walking", "walks slowly", 0.6), draw("walking", "strolls slowly", 0.8),
                                    draw("walking", "walks slowly", 1.0), draw("walking", "walks quickly", 1.5),
                                    draw("walking", "hurries", 1.7),      draw("walking", "walks fast", 1.9),
                                    draw("walking", "walks", 5.0),  // asks no pace: not counted
                                    draw("running", "jogs", 2.0),         draw("running", "sprints", 5.0)};
    const AttributeBenchmark b = attribute_benchmark(d);
    ASSERT_EQ(b.speed.count("walking"), 1u);
    EXPECT_DOUBLE_EQ(b.speed.at("walking").ratio(), 1.7 / 0.8);
    EXPECT_EQ(b.speed.at("walking").slow_draws, 3);
    EXPECT_DOUBLE_EQ(b.speed.at("running").ratio(), 2.5);
}

TEST(AttributeBenchmark, TurnsCountOnlyInTheAskedDirectionAndSize) {
    const AttributeBenchmark b = attribute_benchmark(
        {draw("walking", "walks and turns left", 1, 60), draw("walking", "turns to the left", 1, -60),
         draw("walking", "turns left", 1, 20), draw("walking", "turns right", 1, -90),
         draw("walking", "turns around", 1, -170), draw("walking", "turns around", 1, 100)});
    EXPECT_EQ(b.checks.at("turn_left").passed, 1);
    EXPECT_EQ(b.checks.at("turn_left").checked, 3);
    EXPECT_EQ(b.checks.at("turn_right").passed, 1);
    EXPECT_EQ(b.checks.at("turn_around").passed, 1);
    EXPECT_EQ(b.checks.at("turn_around").checked, 2);
    EXPECT_EQ(b.checks.count("backward"), 0u);
}

TEST(AttributeBenchmark, BackwardAndSequences) {
    AttributeDraw back = draw("walking", "walks backwards", 1), forward = draw("walking", "walks backward", 1);
    back.attributes.travel = TravelDirection::backward, forward.attributes.travel = TravelDirection::forward;
    // Up 0.6 m and back down over 8 s, against a climb that stays up.
    const AttributeDraw trip = measure_draw("stairs", "goes up the stairs and then back down",
                                            lifted(160, [](int f) { return 0.6 * std::sin(M_PI * f / 159); }));
    const AttributeDraw climb =
        measure_draw("stairs", "walks up and then keeps going", lifted(160, [](int f) { return 0.6 * f / 159; }));
    EXPECT_NEAR(trip.pelvis_peak_above_ends_m, 0.6, 0.01);
    EXPECT_NEAR(climb.pelvis_peak_above_ends_m, 0.0, 1e-9);
    AttributeDraw sit = draw("sitting", "sits down and then stands up", 0),
                  stay = draw("sitting", "sits down and then stands up", 0);
    sit.attributes.transitions = {Transition::sit_down, Transition::stand_up};
    stay.attributes.transitions = {Transition::stand_up, Transition::sit_down};
    const AttributeBenchmark b = attribute_benchmark({back, forward, trip, climb, sit, stay});
    EXPECT_EQ(b.checks.at("backward").passed, 1);
    EXPECT_EQ(b.checks.at("backward").checked, 2);
    EXPECT_EQ(b.checks.at("stairs_up_down").passed, 1);
    EXPECT_EQ(b.checks.at("stairs_up_down").checked, 2);
    EXPECT_EQ(b.checks.at("sit_then_stand").passed, 1);
    EXPECT_NE(attribute_benchmark_json(b).find("\"stairs_up_down\""), std::string::npos);
    EXPECT_NE(attribute_benchmark_table(b).find("sit_then_stand   1 of 2 draws (50 %)"), std::string::npos);
}

TEST(AttributeBenchmark, ASynthFolderWithoutKeptMotionsIsRefused) {
    const std::string dir = test::scratch_dir("attribute_benchmark_empty");
    std::filesystem::create_directories(dir + "/jobs");
    EXPECT_THROW(synth_folder_draws(dir), Error);
}
