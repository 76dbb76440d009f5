// report/activity_confusion: the table's recall and totals from known counts, and the confusion of the report
// fixture's synthesis folder (two kept walk motions, prompted walking and running) against a reference that
// holds the same walk as "walking" beside a motionless "standing".
#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.hpp"
#include "report/activity_confusion.hpp"
#include "report_fixture.hpp"
#include "test_util.hpp"

using namespace t2imu;

TEST(ActivityConfusion, RecallAndTotalsCountOnlyRowsWithAClass) {
    ActivityConfusion t;
    t.columns = {"sitting", "walking"};
    t.rows = {"dancing", "sitting", "walking"};
    t.expected = {"", "sitting", "walking"};
    t.counts = {{1, 2}, {3, 1}, {0, 0}};
    EXPECT_EQ(t.right(), 3);  // sitting 3 of 4; walking none of 0; dancing has no class
    EXPECT_EQ(t.total(), 4);
    EXPECT_EQ(t.csv(), "truth\\predicted,sitting,walking,recall\ndancing,1,2,\nsitting,3,1,0.750\nwalking,0,0,\n");
}

TEST(ActivityConfusion, SynthFolderRowsArePromptedActivitiesOfKeptJobs) {
    const std::string dir = test::scratch_dir("activity_confusion");
    test::write_synth_fixture(dir);
    const JointSequence walk = test::fixture_walk(40);
    JointSequence still = walk;
    for (int f = 0; f < still.num_frames; ++f)
        for (int j = 0; j < still.num_joints; ++j) still.at(f, j) = walk.at(0, j);
    std::vector<ActivityExample> reference;
    for (const char* subject : {"s1", "s2"}) {
        reference.push_back({"walking", subject, describe_motion(walk)});
        reference.push_back({"standing", subject, describe_motion(still)});
    }
    const MotionActivityClassifier classifier(reference);
    const ActivityConfusion t = synth_confusion(classifier, dir);
    ASSERT_EQ(t.rows, (std::vector<std::string>{"running", "walking"}));  // j00002 (walking) was dropped
    ASSERT_EQ(t.columns, (std::vector<std::string>{"standing", "walking"}));
    EXPECT_EQ(t.counts, (std::vector<std::vector<long>>{{0, 1}, {0, 1}}));  // both motions are the walk
    EXPECT_EQ(t.expected, (std::vector<std::string>{"", "walking"}));       // no class of this reference shows running
    EXPECT_EQ(t.right(), 1);
    EXPECT_EQ(t.total(), 1);
    std::filesystem::remove(dir + "/jobs/j00000.json");
    std::filesystem::remove(dir + "/jobs/j00001.json");
    EXPECT_NE(test::error_message([&] { synth_confusion(classifier, dir); }).find("at least one kept motion"),
              std::string::npos);
}
