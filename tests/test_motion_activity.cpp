// The activity classifier against reference sets whose answers are known (the motion descriptors it reads are
// tested in test_motion_descriptors.cpp).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/csv.hpp"
#include "motion/motion_activity.hpp"
#include "motion/skeleton.hpp"
#include "test_util.hpp"

namespace t2imu {
namespace {

// An example whose descriptors are all `value` but descriptor 0, which is `x`.
ActivityExample example(const std::string& activity, const std::string& subject, double x, double value = 0) {
    ActivityExample e{activity, subject, {}};
    e.descriptors.fill(value);
    e.descriptors[0] = x;
    return e;
}

MotionDescriptors point(double x) { return example("", "", x).descriptors; }

TEST(MotionActivity, SmallClassesAreNotOutvotedByLargeOnes) {
    // 100 walking clips spread over x in [0, 1), two sitting clips at x = 2: of the five clips nearest a
    // point at 1.5, three are walking (0.97..0.99) and two sitting, so a 5-nearest-neighbour vote says
    // walking; by the mean distance to each class's 5 (or all 2) nearest clips, 0.5 against 0.53, it is sitting.
    std::vector<ActivityExample> ref;
    for (int i = 0; i < 100; ++i) ref.push_back(example("walking", "w" + std::to_string(i % 4), i / 100.0));
    for (int i = 0; i < 2; ++i) ref.push_back(example("sitting", "s" + std::to_string(i), 2.0));
    const MotionActivityClassifier c(ref);
    const ActivityScores s = c.classify(point(1.5));
    EXPECT_EQ(s.best, "sitting");
    // Distances in standardised units (x over its standard deviation in the reference).
    double mean = 0, mean2 = 0;
    for (const ActivityExample& e : ref)
        mean += e.descriptors[0] / 102.0, mean2 += e.descriptors[0] * e.descriptors[0] / 102.0;
    const double sd = std::sqrt(mean2 - mean * mean);
    EXPECT_NEAR(s.distance.at("sitting"), 0.5 / sd, 1e-9);
    EXPECT_NEAR(s.distance.at("walking"), (1.5 - 0.97) / sd, 1e-9);
    EXPECT_DOUBLE_EQ(s.agreement("sitting"), 1.0);
    EXPECT_NEAR(s.agreement("walking"), 0.5 / 0.53, 1e-9);
    EXPECT_DOUBLE_EQ(s.agreement("flying"), 1.0);  // not a class: not checked
}

TEST(MotionActivity, LeaveOneSubjectOutLeavesTheWholeSubjectOut) {
    // Subject "odd" holds the only running clips near x = 1 and a walking clip at x = 1: without its own
    // clips, its walking clip is nearest the other subjects' running clips.
    const std::vector<ActivityExample> ref = {example("walking", "a", 0.0),   example("walking", "b", 0.1),
                                              example("walking", "odd", 1.0), example("running", "c", 1.05),
                                              example("running", "d", 1.1),   example("running", "odd", 0.95)};
    const MotionActivityClassifier c(ref);
    std::vector<double> agreement;
    const auto confusion = c.leave_one_subject_out(&agreement);
    ASSERT_EQ(c.classes(), (std::vector<std::string>{"running", "walking"}));
    // Rows truth, columns predicted: running's three clips -> running (odd's 0.95 sees c and d nearer than
    // a and b); walking: a and b -> walking, odd's 1.0 -> running.
    EXPECT_EQ(confusion, (std::vector<std::vector<long>>{{3, 0}, {1, 2}}));
    ASSERT_EQ(agreement.size(), 6u);
    EXPECT_LT(agreement[2], 1.0);
}

TEST(MotionActivity, ReferenceTableRoundTripsThroughCsv) {
    std::vector<ActivityExample> ref;
    for (int i = 0; i < 6; ++i)
        ref.push_back(example(i < 3 ? "lying" : "jumping", "s" + std::to_string(i), i * 0.37, i * 0.1));
    const MotionActivityClassifier a(ref);
    const std::string path = test::scratch_dir("motion_activity") + "/reference.csv";
    write_csv(path, a.reference_table());
    const MotionActivityClassifier b = MotionActivityClassifier::load(path);
    for (double x : {0.0, 0.5, 1.2, 3.0}) {
        const ActivityScores sa = a.classify(point(x)), sb = b.classify(point(x));
        EXPECT_EQ(sa.best, sb.best);
        for (const auto& [k, v] : sa.distance) EXPECT_NEAR(sb.distance.at(k), v, 1e-5 * (1 + v));
    }
}

TEST(MotionActivity, RefusesAReferenceOfOneActivity) {
    EXPECT_THROW(MotionActivityClassifier({example("walking", "a", 0), example("walking", "b", 1)}), Error);
}

TEST(MotionActivity, PromptActivitiesMapOntoTheReferenceClasses) {
    const std::vector<std::string> classes = {"jumping", "lying", "running", "sitting", "walking"};
    EXPECT_EQ(reference_activity("jogging", classes), "running");
    EXPECT_EQ(reference_activity("sit_down_stand_up", classes), "sitting");
    EXPECT_EQ(reference_activity("lie_down_get_up_bed", classes), "lying");
    EXPECT_EQ(reference_activity("walking", classes), "walking");
    EXPECT_EQ(reference_activity("stairs_up", classes), "");  // no stairs class: not checked
    EXPECT_EQ(reference_activity("falling", classes), "");
    // With both stair directions as classes, SisFall's pooled class is checked against the nearer of the two.
    const std::vector<std::string> with_stairs = {"stairs_down", "stairs_up", "walking"};
    EXPECT_EQ(reference_activity("stairs_up_down", with_stairs), "stairs");
    EXPECT_EQ(reference_activity("climbingdown", with_stairs), "stairs_down");
    ActivityScores s;
    s.best = "walking";
    s.distance = {{"stairs_down", 2.0}, {"stairs_up", 4.0}, {"walking", 1.0}};
    EXPECT_DOUBLE_EQ(s.agreement("stairs"), 0.5);
    EXPECT_DOUBLE_EQ(s.agreement("stairs_up"), 0.25);
}

}  // namespace
}  // namespace t2imu
