// activity_examples: from a small dataset in the `t2imu data build` layout, only unmirrored clips with exactly
// one activity tag other than "other" and at least 3 frames are examples; subjects are qualified by source (a
// derived clip's by its source clip's dataset); descriptors are those of the clip's joints (a clip gliding at
// 1 m/s has root speed 1); a dataset without any example is refused naming clips.csv and the column.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "data/activity_reference.hpp"
#include "motion/joint_sequence.hpp"
#include "test_util.hpp"

using namespace t2imu;
using Eigen::Vector3d;

namespace {
// A stick figure 0.9 m tall at the pelvis, moving forward at `speed` m/s, for `frames` frames at 20 fps.
JointSequence gliding(int frames, double speed, double pelvis_height) {
    JointSequence m(frames, 22, 20.0);
    for (int f = 0; f < frames; ++f)
        for (int k = 0; k < 22; ++k) {
            // Joint k at height pelvis_height + 0.05 (k - 7) (so the head is above the pelvis), spread sideways.
            m.at(f, k) = Vector3d(0.01 * k, pelvis_height + 0.05 * (k - 7) * (k != 0), speed * f / 20.0);
        }
    for (int f = 0; f < frames; ++f) m.at(f, 0).y() = pelvis_height;
    return m;
}

void add_clip(const std::string& dir, CsvTable& clips, const std::string& id, const std::string& tags,
              const std::string& mirrored, const std::string& subject, const std::string& source,
              const std::string& provenance, const JointSequence& joints) {
    clips.rows.push_back({id, tags, mirrored, subject, source, provenance});
    write_npy(dir + "/new_joints/" + id + ".npy", joint_sequence_to_array(joints));
}

std::string make_dataset(const std::string& name, bool with_examples) {
    const std::string dir = test::scratch_dir(name);
    std::filesystem::create_directories(dir + "/new_joints");
    CsvTable clips;
    clips.header = {"id", "activity_tags", "mirrored", "subject", "source_dataset", "provenance"};
    if (with_examples) {
        add_clip(dir, clips, "000001", "walking", "0", "1", "cmu", "", gliding(40, 1.0, 0.9));
        add_clip(dir, clips, "M000001", "walking", "1", "1", "cmu", "", gliding(40, 1.0, 0.9));  // mirrored copy
        add_clip(dir, clips, "000003", "sitting", "0", "1", "hdm05", "", gliding(30, 0.0, 0.5));
        add_clip(dir, clips, "000004", "stairs_up", "0", "1", "edited",
                 R"({"derived_from":"a.bvh","source_dataset":"cmu","method":"stairs"})",
                 gliding(30, 0.4, 0.9));                                                          // derived
        add_clip(dir, clips, "000005", "running", "0", "2", "bandai", "", gliding(2, 3.0, 0.9));  // 2 frames
    }
    add_clip(dir, clips, "000002", "walking;running", "0", "1", "cmu", "", gliding(40, 2.0, 0.9));  // two tags
    add_clip(dir, clips, "000006", "other", "0", "3", "cmu", "", gliding(40, 0.5, 0.9));
    add_clip(dir, clips, "000007", "", "0", "3", "cmu", "", gliding(40, 0.5, 0.9));
    write_csv(dir + "/clips.csv", clips);
    return dir;
}
}  // namespace

TEST(ActivityReference, KeepsSingleTaggedUnmirroredClips) {
    const std::vector<ActivityExample> e = activity_examples(make_dataset("activity_reference_ok", true));
    ASSERT_EQ(e.size(), 3u);
    std::map<std::string, ActivityExample> by_activity;
    for (const ActivityExample& x : e) by_activity[x.activity] = x;
    ASSERT_EQ(by_activity.count("walking"), 1u);
    ASSERT_EQ(by_activity.count("sitting"), 1u);
    ASSERT_EQ(by_activity.count("stairs_up"), 1u);
    // Subjects qualified by source; the derived clip counts as its source clip's subject.
    EXPECT_EQ(by_activity["walking"].subject, "cmu:1");
    EXPECT_EQ(by_activity["sitting"].subject, "hdm05:1");
    EXPECT_EQ(by_activity["stairs_up"].subject, "cmu:1");
    // Descriptors of the clip's own joints: root speed (index 6) and pelvis height (index 0).
    EXPECT_NEAR(by_activity["walking"].descriptors[6], 1.0, 1e-5);
    EXPECT_NEAR(by_activity["sitting"].descriptors[6], 0.0, 1e-6);
    EXPECT_NEAR(by_activity["stairs_up"].descriptors[6], 0.4, 1e-5);
    EXPECT_NEAR(by_activity["sitting"].descriptors[0], 0.5, 1e-6);
}

TEST(ActivityReference, ADatasetWithoutExamplesIsRefused) {
    const std::string dir = make_dataset("activity_reference_none", false);
    try {
        activity_examples(dir);
        ADD_FAILURE() << "no examples accepted";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find(dir + "/clips.csv"), std::string::npos) << m;
        EXPECT_NE(m.find("activity_tags"), std::string::npos) << m;
    }
}

TEST(ActivityReference, AMissingColumnIsRefusedByName) {
    const std::string dir = test::scratch_dir("activity_reference_column");
    std::ofstream(dir + "/clips.csv") << "id,activity_tags,subject,source_dataset\n000001,walking,1,cmu\n";
    try {
        activity_examples(dir);
        ADD_FAILURE() << "clips.csv without `mirrored` accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("mirrored"), std::string::npos) << e.what();
    }
}
