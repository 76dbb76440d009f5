// The RealWorld loader on a proband folder written here in the release's exact format.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/atomic_file.hpp"
#include "core/zip_archive.hpp"
#include "har/datasets/realworld.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

// A stream on its own clock: samples from start_ms every step_ms until end_ms; value = f(t_ms).
std::vector<uint8_t> stream_csv(double start_ms, double step_ms, double end_ms, double (*fx)(double), double y,
                                double z) {
    std::string s = "id,attr_time,attr_x,attr_y,attr_z\n";
    int id = 1;
    for (double t = start_ms; t <= end_ms; t += step_ms) {
        char line[160];
        std::snprintf(line, sizeof line, "%d,%.0f,%.9f,%.9f,%.9f\n", id++, t, fx(t), y, z);
        s += line;
    }
    return std::vector<uint8_t>(s.begin(), s.end());
}

double acc_x(double t) { return 0.001 * t; }
double gyr_x(double t) { return 0.0005 * t; }

std::string make_proband() {
    namespace fs = std::filesystem;
    const std::string dir = test::scratch_dir("realworld") + "/proband3";
    fs::create_directories(dir + "/data");
    write_zip(dir + "/data/acc_walking_csv.zip",
              {{"acc_walking_chest.csv", stream_csv(1000, 20, 3000, acc_x, 9.81, 0)},
               {"acc_walking_waist.csv", stream_csv(1010, 20, 3100, acc_x, 9.7, 0)},
               {"acc_walking_thigh.csv", stream_csv(1000, 20, 3000, acc_x, 9.7, 0)}});
    write_zip(dir + "/data/gyr_walking_csv.zip",
              {{"Gyroscope_walking_chest.csv", stream_csv(1005, 20, 2990, gyr_x, 0, 1)},
               {"Gyroscope_walking_waist.csv", stream_csv(995, 20, 3100, gyr_x, 0, 1)}});
    // Climbing, split into parts, with the accelerometer part inside a nested zip.
    ZipMembers inner = {{"acc_climbingdown_2_chest.csv", stream_csv(0, 20, 1000, acc_x, 9.81, 0)}};
    const std::string inner_path = dir + "/inner.zip";
    write_zip(inner_path, inner);
    write_zip(dir + "/data/acc_climbingdown_csv.zip", {{"acc_climbingdown_2_csv.zip", read_file_bytes(inner_path)}});
    write_zip(dir + "/data/gyr_climbingdown_csv.zip",
              {{"Gyroscope_climbingdown_2_chest.csv", stream_csv(0, 20, 1000, gyr_x, 0, 1)}});
    fs::remove(inner_path);
    return dir;
}

}  // namespace

TEST(RealWorld, AlignsPositionsOnOneGridAndReadsNestedParts) {
    std::vector<std::string> skipped;
    const std::vector<ImuRecording> recs = read_realworld_proband(make_proband(), &skipped);
    ASSERT_EQ(recs.size(), 3u);  // walking chest + waist, stairs_down part 2 chest; the thigh has no gyroscope
    ASSERT_EQ(skipped.size(), 1u);
    EXPECT_NE(skipped[0].find("thigh"), std::string::npos);
    std::map<std::string, const ImuRecording*> by_path;
    for (const ImuRecording& r : recs) by_path[r.path] = &r;
    const ImuRecording& chest = *by_path.at("realworld/proband3/walking_1_seg0_chest.csv");
    const ImuRecording& waist = *by_path.at("realworld/proband3/walking_1_seg0_waist.csv");
    EXPECT_EQ(chest.subject, "proband3");
    // Common grid: from the latest first sample (waist acc, 1010 ms) to the earliest last one (chest gyro, 2985 ms).
    EXPECT_EQ(chest.extra.at("start_ms"), "1010");
    EXPECT_EQ(chest.samples.size(), waist.samples.size());
    EXPECT_EQ(chest.samples.size(), static_cast<size_t>((2985 - 1010) / 20) + 1);
    for (size_t i = 0; i < chest.samples.size(); ++i) {
        const double t_ms = 1010 + 20.0 * static_cast<double>(i);
        EXPECT_NEAR(chest.t[i], i / 50.0, 1e-12);
        EXPECT_NEAR(chest.samples[i][0], acc_x(t_ms), 1e-9);  // linear signals interpolate exactly
        EXPECT_NEAR(chest.samples[i][3], gyr_x(t_ms), 1e-9);
        EXPECT_NEAR(waist.samples[i][0], acc_x(t_ms), 1e-9);
        EXPECT_NEAR(waist.samples[i][1], 9.7, 1e-9);
        EXPECT_NEAR(waist.samples[i][5], 1.0, 1e-9);
    }
    const ImuRecording& stairs = *by_path.at("realworld/proband3/stairs_down_2_seg0_chest.csv");
    EXPECT_EQ(stairs.activity, "stairs_down");
    EXPECT_EQ(stairs.samples.size(), 51u);
}
