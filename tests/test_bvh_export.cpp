#include <gtest/gtest.h>

#include <filesystem>

#include "core/npy.hpp"
#include "motion/bvh_export.hpp"
#include "motion/mocap_import.hpp"
#include "test_util.hpp"

using namespace t2imu;

TEST(BvhExport, ImportOfTheExportGivesTheJointsBack) {
    std::string input;
    SHARED_OR_SKIP(input, "reference/humanml3d/generated/seq_synth_turn/input_joints.npy");
    // A turning walk with 1 mm noise: bone lengths change slightly from frame to frame, which the exporter must
    // carry too.
    const JointSequence joints = joint_sequence_from_array(read_npy(input), input);
    const std::string dir = test::scratch_dir("bvh_export");
    write_bvh(dir + "/turn.bvh", smpl22_to_bvh(joints));
    const JointSequence back = import_motion(dir + "/turn.bvh");
    ASSERT_EQ(back.num_frames, joints.num_frames);
    double worst = 0;
    for (size_t i = 0; i < joints.positions.size(); ++i)
        worst = std::max(worst, (back.positions[i] - joints.positions[i]).norm());
    EXPECT_LT(worst, 1e-4);
}

TEST(BvhExport, CliImportExportRoundTrip) {
    const std::string bvh = test::source_dir() + "/examples/cmu_07_05_slow_walk.bvh";
    const std::string dir = test::scratch_dir("bvh_export_cli");
    auto r = test::run_cli("motion import " + bvh + " --out " + dir + "/j.npy");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    r = test::run_cli("motion export " + dir + "/j.npy --out " + dir + "/j.bvh");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    r = test::run_cli("motion import " + dir + "/j.bvh --out " + dir + "/j2.npy");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::vector<double> a = read_npy(dir + "/j.npy").to<double>(), b = read_npy(dir + "/j2.npy").to<double>();
    ASSERT_EQ(a.size(), 87u * 22 * 3);
    ASSERT_EQ(a.size(), b.size());
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::fabs(a[i] - b[i]));
    EXPECT_LT(worst, 1e-4);
    // A garbage file: one line naming it, exit 1, no output.
    std::FILE* f = std::fopen((dir + "/garbage.bvh").c_str(), "w");
    std::fputs("HIERARCHY\nROOT x {", f);
    std::fclose(f);
    r = test::run_cli("motion import " + dir + "/garbage.bvh --out " + dir + "/g.npy");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.output.find("garbage.bvh"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir + "/g.npy"));
}
