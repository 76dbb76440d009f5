// Every motion-capture file of the shared set imports, and the result is a plausible human motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include <Eigen/Geometry>

#include "core/error.hpp"
#include "motion/mocap_import.hpp"
#include "motion/skeleton.hpp"
#include "test_util.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {

struct Plausibility {
    double bone_deviation = 0;   // max |length - median length| over bones (but the neck->head one) and frames, m
    double head_deviation = 0;   // the same for the neck->head bone
    double standing_height = 0;  // max over frames of head-joint height above the lower foot + 0.12 m
    double lowest_foot = 0;      // min over frames of the lower foot joint's height (metres, floor y = 0)
    double max_step = 0;         // max per-frame displacement of any joint (metres)
    double forward_travel = 0;   // root travel along the body's forward direction (metres)
};

Plausibility measure(const JointSequence& s) {
    Plausibility p;
    p.lowest_foot = 1e9;
    for (int j = 1; j < 22; ++j) {
        std::vector<double> len;
        for (int f = 0; f < s.num_frames; ++f)
            len.push_back((s.at(f, j) - s.at(f, smpl22::kParents[static_cast<size_t>(j)])).norm());
        std::nth_element(len.begin(), len.begin() + static_cast<long>(len.size() / 2), len.end());
        const double median = len[len.size() / 2];
        double& dev = j == smpl22::head ? p.head_deviation : p.bone_deviation;
        for (double l : len) dev = std::max(dev, std::fabs(l - median));
    }
    for (int f = 0; f < s.num_frames; ++f) {
        double foot = 1e9;
        for (int j : {7, 8, 10, 11}) foot = std::min(foot, s.at(f, j).y());
        p.lowest_foot = std::min(p.lowest_foot, foot);
        p.standing_height = std::max(p.standing_height, s.at(f, smpl22::head).y() - foot + 0.12);
        if (f > 0)
            for (int j = 0; j < 22; ++j) p.max_step = std::max(p.max_step, (s.at(f, j) - s.at(f - 1, j)).norm());
        if (f > 0) {
            const Eigen::Vector3d across = s.at(f, smpl22::left_hip) - s.at(f, smpl22::right_hip);
            const Eigen::Vector3d forward = across.cross(Eigen::Vector3d::UnitY()).normalized();
            p.forward_travel += forward.dot(s.at(f, 0) - s.at(f - 1, 0));
        }
    }
    return p;
}

std::vector<std::string> files_in(const std::string& dir, const std::string& ext) {
    std::vector<std::string> out;
    if (dir.empty() || !fs::is_directory(dir)) return out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ext) out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

struct Archive {
    const char* archive;
    const char* folder;
    const char* ext;
};
const Archive kArchives[] = {
    {"mocap/cmu_daz_bvh_20fps.tar.xz", "bvh20", ".bvh"},
    {"mocap/cmu_iclone_bvh_20fps.tar.xz", "bvh20_iclone", ".bvh"},
    {"mocap/cmu_daz_bvh_native.tar.xz", "native", ".bvh"},
    {"mocap/hdm05_amc_native.tar.xz", "hdm05_amc", ".amc"},
    {"mocap/bandai_bvh_native.tar.xz", "bandai_bvh", ".bvh"},
    {"mocap/reactidle_bvh.tar.xz", "reactidle_bvh", ".bvh"},
};

// Clips whose capture walks or runs forward, by file name.
bool moves_forward(const std::string& path) {
    const std::string name = fs::path(path).filename().string();
    return name.find("_walk_") != std::string::npos || name.find("_run_") != std::string::npos;
}

}  // namespace

TEST(MocapImport, EveryFileImportsPlausibly) {
    std::string manifest;
    SHARED_OR_SKIP(manifest, "mocap/manifest.csv");
    int files = 0, forward_clips = 0, forward_ok = 0;
    Plausibility worst;
    worst.lowest_foot = 0;
    double min_height = 1e9, max_height = 0, min_floor = 1e9, max_floor = -1e9;
    std::string worst_bone_file, min_height_file, max_height_file;
    for (const Archive& a : kArchives) {
        const std::string root = test::unpacked_shared_archive(a.archive);
        ASSERT_FALSE(root.empty()) << a.archive;
        for (const std::string& path : files_in(root + "/" + a.folder, a.ext)) {
            ++files;
            JointSequence s;
            try {
                s = import_motion(path);
            } catch (const Error& e) {
                ADD_FAILURE() << e.what();
                continue;
            }
            ASSERT_GE(s.num_frames, 2) << path;
            const Plausibility p = measure(s);
            if (p.bone_deviation > worst.bone_deviation) {
                worst.bone_deviation = p.bone_deviation;
                worst_bone_file = path;
            }
            worst.max_step = std::max(worst.max_step, p.max_step);
            if (p.standing_height < min_height) {
                min_height = p.standing_height;
                min_height_file = path;
            }
            if (p.standing_height > max_height) {
                max_height = p.standing_height;
                max_height_file = path;
            }
            min_floor = std::min(min_floor, p.lowest_foot);
            max_floor = std::max(max_floor, p.lowest_foot);
            EXPECT_LT(p.bone_deviation, 1e-6) << path;  // rigid bones
            // SMPL's neck->head spans two source bones in HDM05 (lowerneck, upperneck), and Bandai Namco animates
            // the head joint's translation: their lengths vary by up to 1.8 cm.
            EXPECT_LT(p.head_deviation, 0.02) << path;
            worst.head_deviation = std::max(worst.head_deviation, p.head_deviation);
            // Head joint above the feet + 12 cm to the crown. Bandai's Head joint sits at the skull base, which
            // puts its crouched dashes at 1.32 m by this estimate.
            EXPECT_GT(p.standing_height, 1.3) << path;
            EXPECT_LT(p.standing_height, 2.0) << path;
            EXPECT_LT(p.max_step, 1.0) << path;  // < 20 m/s: no flips
            if (moves_forward(path)) {
                ++forward_clips;
                forward_ok += p.forward_travel > 0;  // left is +X when facing +Z
            }
        }
    }
    EXPECT_EQ(files, 99 + 41 + 5 + 287 + 666 + 22);
    EXPECT_EQ(forward_ok, forward_clips) << "clips walking or running forward must move along the body's forward";
    std::printf(
        "[ mocap    ] %d files; bone length deviation max %.2e m (%s), neck->head %.3f m; standing height %.3f (%s) .. "
        "%.3f m (%s); "
        "lowest foot per clip %.3f .. %.3f m; max joint step %.3f m/frame; %d/%d forward clips move forward\n",
        files, worst.bone_deviation, worst_bone_file.c_str(), worst.head_deviation, min_height, min_height_file.c_str(),
        max_height, max_height_file.c_str(), min_floor, max_floor, worst.max_step, forward_ok, forward_clips);
}

TEST(MocapImport, NativeRateFilesAgreeWithTheir20FpsVersions) {
    std::string manifest;
    SHARED_OR_SKIP(manifest, "mocap/manifest.csv");
    const std::string native = test::unpacked_shared_archive("mocap/cmu_daz_bvh_native.tar.xz") + "/native";
    const std::string low = test::unpacked_shared_archive("mocap/cmu_daz_bvh_20fps.tar.xz") + "/bvh20";
    double worst = 0;
    int compared = 0;
    for (const std::string& path : files_in(native, ".bvh")) {
        const std::string twin = low + "/" + fs::path(path).filename().string();
        if (!fs::exists(twin)) continue;
        // 120 fps with its T-pose frame, resampled to 20 fps, against the shipped decimation (source frames
        // 1, 7, 13, ...): the resampling times fall on source frames, so the two must agree to rounding.
        const JointSequence a = import_motion(path), b = import_motion(twin);
        ASSERT_EQ(a.num_frames, b.num_frames) << path;
        for (size_t i = 0; i < a.positions.size(); ++i)
            worst = std::max(worst, (a.positions[i] - b.positions[i]).norm());
        ++compared;
    }
    EXPECT_EQ(compared, 5);
    EXPECT_LT(worst, 1e-4);  // the 20 fps files are written with 6 significant digits
    std::printf("[ mocap    ] native 120 fps vs shipped 20 fps: %d clips, max joint difference %.2e m\n", compared,
                worst);
}

TEST(MocapImport, CaptureRateKeepsCapturedFramesOnly) {
    EXPECT_DOUBLE_EQ(capture_fps_for(120), 60);
    EXPECT_DOUBLE_EQ(capture_fps_for(1 / 0.00833333), 1 / 0.00833333 / 2);  // as BVH files print 1/120 s
    EXPECT_DOUBLE_EQ(capture_fps_for(30), 30);
    EXPECT_DOUBLE_EQ(capture_fps_for(24), 24);
    EXPECT_DOUBLE_EQ(capture_fps_for(100), 50);
    EXPECT_DOUBLE_EQ(capture_fps_for(250), 250.0 / 5);
    EXPECT_THROW(capture_fps_for(0), Error);
    std::string manifest;
    SHARED_OR_SKIP(manifest, "mocap/manifest.csv");
    // A 120 fps file at fps 0 is every second captured frame: the 20 fps import's frames are every third of them.
    const std::string native = test::unpacked_shared_archive("mocap/cmu_daz_bvh_native.tar.xz") + "/native";
    const std::string path = files_in(native, ".bvh").front();
    ImportOptions capture;
    capture.fps = 0;
    const JointSequence a = import_motion(path, capture), b = import_motion(path);
    EXPECT_NEAR(a.fps, 60, 1e-3);
    EXPECT_EQ((a.num_frames - 1) / 3, b.num_frames - 1);
    for (int f = 0; f < b.num_frames; ++f)
        for (int j = 0; j < 22; ++j) ASSERT_LT((a.at(3 * f, j) - b.at(f, j)).norm(), 1e-9) << f;
    ImportOptions npy = capture;
    npy.format = "npy";
    EXPECT_THROW(import_motion(path, npy), Error);  // an .npy does not know its rate
}

TEST(MocapImport, RefusesUnknownSkeletonNamingTheJoints) {
    const std::string dir = test::scratch_dir("mocap_unknown_skeleton");
    const std::string path = dir + "/robot.bvh";
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fputs(
        "HIERARCHY\nROOT base\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation "
        "Yrotation\n"
        " JOINT arm\n {\n  OFFSET 0 10 0\n  CHANNELS 1 Zrotation\n  End Site\n  {\n   OFFSET 0 5 0\n  }\n }\n}\n"
        "MOTION\nFrames: 2\nFrame Time: 0.05\n0 0 0 0 0 0 10\n0 0 0 0 0 0 20\n",
        f);
    std::fclose(f);
    try {
        import_motion(path);
        FAIL() << "an unknown skeleton must be refused";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("robot.bvh"), std::string::npos) << m;
        EXPECT_NE(m.find("pelvis"), std::string::npos) << m;
        EXPECT_NE(m.find("left_wrist"), std::string::npos) << m;
    }
}

TEST(MocapImport, ZUpSourcesAreTurnedToYUp) {
    const std::string bvh = test::source_dir() + "/examples/cmu_07_05_slow_walk.bvh";
    ImportOptions z;
    z.up = 'z';
    const JointSequence a = import_motion(bvh), b = import_motion(bvh, z);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    for (size_t i = 0; i < a.positions.size(); ++i)
        EXPECT_LT(
            (b.positions[i] - Eigen::Vector3d(a.positions[i].x(), a.positions[i].z(), -a.positions[i].y())).norm(),
            1e-12);
    z.up = 'x';
    EXPECT_THROW(import_motion(bvh, z), Error);
}
