// One data set's sensor axes in another's (imu/reframe): the waist conventions of UMAFall (x up, z out of the
// skin) and SisFall (y down, z forward) differ by an exact axis permutation; a virtual UMAFall tag turned into
// SisFall's axes reads what a virtual SisFall board at the same spot reads; `t2imu data reframe` writes that
// turn, records the frame and turns back without being told where from.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "body/procedural_body.hpp"
#include "imu/reframe.hpp"
#include "imu/virtual_imu.hpp"
#include "test_util.hpp"

using namespace t2imu;
using Eigen::AngleAxisd;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

const SensorPlacement& placement_in(const std::string& set, const std::string& position) {
    static std::map<std::string, PlacementSet> sets;
    if (!sets.count(set)) sets[set] = builtin_placement_set(set);
    return placement_at(sets[set], position, "test");
}

ImuRecording as_recording(const ImuSignals& s) {
    ImuRecording r;
    r.t = s.t;
    for (size_t k = 0; k < s.t.size(); ++k)
        r.samples.push_back({s.acc[k].x(), s.acc[k].y(), s.acc[k].z(), s.gyr[k].x(), s.gyr[k].y(), s.gyr[k].z()});
    return r;
}

// The rest skeleton of `body` bouncing 4 cm at 1.5 Hz while it yaws 0.3 rad at 0.8 Hz and rolls 0.1 rad at 1.1 Hz.
JointSequence bouncing_turning(const BodyModel& body) {
    const double fps = 20;
    JointSequence seq(61, smpl22::kNumJoints, fps);
    for (int f = 0; f < 61; ++f) {
        const double t = f / fps;
        const Matrix3d r = (AngleAxisd(0.3 * std::sin(2 * M_PI * 0.8 * t), Vector3d::UnitY()) *
                            AngleAxisd(0.1 * std::sin(2 * M_PI * 1.1 * t), Vector3d::UnitZ()))
                               .toRotationMatrix();
        const Vector3d x(0.2 * t, 0.04 * std::sin(2 * M_PI * 1.5 * t), 0);
        for (int j = 0; j < smpl22::kNumJoints; ++j) seq.at(f, j) = r * body.rest_joints()[static_cast<size_t>(j)] + x;
    }
    return seq;
}

}  // namespace

TEST(Reframe, UmafallWaistInSisfallAxesIsTheAxisPermutation) {
    // UMAFall x up, y right, z front; SisFall x right, y down, z front: x_s = y_u, y_s = -x_u, z_s = z_u, on
    // any body (the waist's front is left-right symmetric).
    Matrix3d expected;
    expected << 0, 1, 0, -1, 0, 0, 0, 0, 1;
    for (const BodySpec& spec : paper_bodies()) {
        const ProceduralBody body(spec);
        const Matrix3d r = reframe_rotation(body, placement_in("umafall", "waist"), placement_in("sisfall", "waist"));
        EXPECT_LT((r - expected).cwiseAbs().maxCoeff(), 1e-12) << spec.name << "\n" << r;
    }
}

TEST(Reframe, ThereAndBackIsTheIdentity) {
    const ProceduralBody body(paper_bodies()[7]);
    const std::pair<const char*, const char*> pairs[] = {
        {"umafall", "realworld"}, {"sisfall", "realworld"}, {"umafall", "sisfall"}};
    for (const auto& [a, b] : pairs)
        for (const char* position : {"waist", "chest"}) {
            if (std::string(position) == "chest" && (std::string(a) == "sisfall" || std::string(b) == "sisfall"))
                continue;
            const Matrix3d ab = reframe_rotation(body, placement_in(a, position), placement_in(b, position));
            const Matrix3d ba = reframe_rotation(body, placement_in(b, position), placement_in(a, position));
            EXPECT_LT((ba * ab - Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-12)
                << a << " " << b << " " << position;
            EXPECT_NEAR(ab.determinant(), 1.0, 1e-12);
        }
}

TEST(Reframe, VirtualUmafallTagReadsAsTheVirtualSisfallBoard) {
    const BodySpec& spec = paper_bodies()[3];
    const ProceduralBody body(spec);
    const JointSequence motion = bouncing_turning(body);
    const BodyImu tag = synthesize_body_imu(motion, spec, parse_sensor_sets("umafall"), {});
    const BodyImu board = synthesize_body_imu(motion, spec, parse_sensor_sets("sisfall"), {});
    ImuRecording turned = as_recording(tag.signals[1]);  // umafall: ankle, waist, chest, wrist
    ASSERT_EQ(tag.mounts[1].placement.position, "waist");
    reframe_recording(reframe_rotation(body, tag.mounts[1].placement, board.mounts[0].placement), turned);
    const ImuRecording expected = as_recording(board.signals[0]);
    ASSERT_EQ(turned.samples.size(), expected.samples.size());
    double worst = 0, largest = 0;
    for (size_t k = 0; k < expected.samples.size(); ++k)
        for (int c = 0; c < 6; ++c) {
            worst = std::max(worst, std::fabs(turned.samples[k][c] - expected.samples[k][c]));
            largest = std::max(largest, std::fabs(expected.samples[k][c]));
        }
    EXPECT_GT(largest, 9.0);  // gravity and the bounce are there to be turned
    EXPECT_LT(worst, 1e-9);
}

TEST(Reframe, CommandWritesTheFrameAndTurnsBackByIt) {
    namespace fs = std::filesystem;
    const std::string dir = test::scratch_dir("reframe_cli");
    fs::create_directories(dir + "/uma/s1");
    std::ofstream(dir + "/uma/manifest.csv")
        << "path,dataset,subject,activity,position,rate_hz,n_samples,units\n"
           "s1/w.csv,umafall,s1,walking,waist,20,3,-\ns1/c.csv,umafall,s1,walking,chest,20,3,-\n";
    const std::string rows =
        "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n0,9.5,0.25,-1.5,0.1,0.2,0.3\n0.05,9.75,-0.5,2,0,0,-0.4\n0.1,9,1,0.5,1,-"
        "1,0\n";
    std::ofstream(dir + "/uma/s1/w.csv") << rows;
    std::ofstream(dir + "/uma/s1/c.csv") << rows;
    const test::CliResult there =
        test::run_cli("data reframe " + dir + "/uma --to sisfall --positions waist --out " + dir + "/sis");
    ASSERT_EQ(there.exit_code, 0) << there.output;
    const std::vector<ImuRecording> sis = read_imu_dataset(dir + "/sis");
    ASSERT_EQ(sis.size(), 1u);  // the chest has no SisFall placement: left out by --positions
    EXPECT_EQ(sis[0].extra.at("frame"), "sisfall");
    EXPECT_EQ(sis[0].dataset, "umafall");
    const std::array<double, 6> first = {0.25, -9.5, -1.5, 0.2, -0.1, 0.3};  // x_s = y_u, y_s = -x_u, z_s = z_u
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(sis[0].samples[0][c], first[c], 1e-9) << c;
    const test::CliResult back = test::run_cli("data reframe " + dir + "/sis --to umafall --out " + dir + "/back");
    ASSERT_EQ(back.exit_code, 0) << back.output;
    const std::vector<ImuRecording> original = read_imu_dataset(dir + "/uma"),
                                    returned = read_imu_dataset(dir + "/back");
    for (size_t k = 0; k < 3; ++k)
        for (int c = 0; c < 6; ++c)
            EXPECT_NEAR(returned[0].samples[k][c], original[0].samples[k][c], 1e-9) << k << " " << c;
}
