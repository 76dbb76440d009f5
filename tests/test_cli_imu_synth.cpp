// t2imu imu synth end to end: files, meta.json, the RealWorld layout read back by our RealWorld loader, refusals.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "body/procedural_body.hpp"
#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/npy.hpp"
#include "core/zip_archive.hpp"
#include "har/datasets/realworld.hpp"
#include "test_util.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {

// A standing average man, 2 s at 20 fps, written as joints .npy.
std::string write_standing(const std::string& dir, int frames = 41) {
    const ProceduralBody body(paper_bodies()[2]);
    std::vector<float> v;
    for (int f = 0; f < frames; ++f)
        for (const Eigen::Vector3d& j : body.rest_joints())
            for (int c = 0; c < 3; ++c) v.push_back(static_cast<float>(j[c]));
    const std::string path = dir + "/standing.npy";
    write_npy(path, NdArray::from(v, {frames, 22, 3}));
    return path;
}

}  // namespace

TEST(CliImuSynth, WritesOneCsvPerBodyAndPositionWithMeta) {
    const std::string dir = test::scratch_dir("cli_imu_synth");
    const std::string joints = write_standing(dir);
    const auto r = test::run_cli("imu synth --joints " + joints +
                                 " --body paper8+height=172,mass=70,sex=f --sensors realworld,hugadb.toml"
                                 " --rate 50 --out " +
                                 dir + "/out");
    // hugadb.toml does not exist: refused before anything is written.
    EXPECT_NE(r.exit_code, 0);
    EXPECT_FALSE(fs::exists(dir + "/out"));
    const auto ok = test::run_cli("imu synth --joints " + joints +
                                  " --body paper8+height=172,mass=70,sex=f --sensors realworld"
                                  " --rate 50 --out " +
                                  dir + "/out");
    ASSERT_EQ(ok.exit_code, 0) << ok.output;
    const CsvTable chest = read_csv(dir + "/out/female_short/chest.csv");
    EXPECT_EQ(chest.header, (std::vector<std::string>{"t", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"}));
    ASSERT_EQ(chest.rows.size(), 101u);                     // 2 s at 50 Hz, both ends included
    EXPECT_NEAR(std::stod(chest.rows[50][2]), 9.81, 1e-6);  // upright phone: y reads +g
    const nlohmann::json meta = nlohmann::json::parse(read_file_text(dir + "/out/meta.json"));
    ASSERT_EQ(meta["bodies"].size(), 9u);
    EXPECT_EQ(meta["bodies"][8]["name"], "h172_m70_f");
    EXPECT_EQ(meta["bodies"][8]["sex"], "female");
    EXPECT_DOUBLE_EQ(meta["bodies"][0]["height_m"].get<double>(), 2.0);
    EXPECT_EQ(meta["bodies"][0]["placements"].size(), 7u);
    EXPECT_EQ(meta["rate_hz"], 50.0);
    EXPECT_EQ(meta["frames"], 41);
    EXPECT_TRUE(meta["bodies"][2]["fit_error_mm"].contains("left_wrist"));
    for (const auto& b : meta["bodies"])
        EXPECT_TRUE(fs::exists(dir + "/out/" + b["name"].get<std::string>() + "/left_thigh.csv"));
}

// imu/realworld_export.cpp (what --format realworld writes), read back by har/datasets/realworld.cpp.
TEST(CliImuSynth, RealWorldFilesReadBackThroughTheRealWorldLoader) {
    const std::string dir = test::scratch_dir("cli_imu_synth_rw");
    const auto r =
        test::run_cli("imu synth --joints " + write_standing(dir) +
                      " --body preset:male_tall --sensors realworld"
                      " --format realworld --activity standing --realism none+sensor=smartphone --seed 3 --out " +
                      dir + "/out");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string body_dir = dir + "/out/male_tall";
    // Pack the files as RealWorld ships them: proband<N>/data/{acc,gyr}_<activity>_csv.zip.
    ZipMembers acc, gyr;
    for (const char* position : {"chest", "forearm", "head", "shin", "thigh", "upperarm", "waist"}) {
        const std::string a = std::string("acc_standing_") + position + ".csv",
                          g = std::string("Gyroscope_standing_") + position + ".csv";
        acc[a] = read_file_bytes(body_dir + "/" + a);
        gyr[g] = read_file_bytes(body_dir + "/" + g);
    }
    fs::create_directories(dir + "/proband1/data");
    write_zip(dir + "/proband1/data/acc_standing_csv.zip", acc);
    write_zip(dir + "/proband1/data/gyr_standing_csv.zip", gyr);
    std::vector<std::string> skipped;
    const std::vector<ImuRecording> recs = read_realworld_proband(dir + "/proband1", &skipped);
    ASSERT_EQ(recs.size(), 7u);
    const CsvTable ours = read_csv(body_dir + "/chest.csv");
    for (const ImuRecording& rec : recs) {
        if (rec.position != "chest") continue;
        EXPECT_EQ(rec.activity, "standing");
        ASSERT_GE(rec.samples.size(), 99u);
        for (size_t k = 0; k < rec.samples.size(); k += 10)
            for (int c = 0; c < 6; ++c) EXPECT_NEAR(rec.samples[k][c], std::stod(ours.rows[k][c + 1]), 1e-5);
    }
}

TEST(CliImuSynth, RefusesBadJointsWithOneLineAndNoOutput) {
    const std::string dir = test::scratch_dir("cli_imu_synth_bad");
    std::vector<float> nan(10 * 22 * 3, 0.5f);
    nan[40] = std::nanf("");
    write_npy(dir + "/nan.npy", NdArray::from(nan, {10, 22, 3}));
    write_npy(dir + "/short.npy", NdArray::from(std::vector<float>(3 * 22 * 3, 0.5f), {3, 22, 3}));
    write_npy(dir + "/shape.npy", NdArray::from(std::vector<float>(10 * 24 * 3, 0.5f), {10, 24, 3}));
    for (const char* bad : {"nan.npy", "short.npy", "shape.npy"}) {
        const auto r = test::run_cli(std::string("imu synth --joints ") + dir + "/" + bad + " --out " + dir + "/out");
        EXPECT_EQ(r.exit_code, 1) << bad << ": " << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        EXPECT_NE(r.output.find(bad), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(dir + "/out"));
    }
}
