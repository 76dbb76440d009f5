// imu/imu_dataset.cpp, the one reader and writer of the IMU dataset format: round trips, number formatting,
// the manifest written alone after recordings written one at a time, and refused files naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "imu/imu_dataset.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

ImuSignals signals(size_t n, double rate) {
    ImuSignals s;
    s.rate_hz = rate;
    for (size_t k = 0; k < n; ++k) {
        s.t.push_back(static_cast<double>(k) / rate);
        s.acc.push_back(Eigen::Vector3d(0.05 * static_cast<double>(k), -9.80665, 1.0 / 3.0));
        s.gyr.push_back(Eigen::Vector3d(0, -0.0000001, 2.5));
    }
    return s;
}

}  // namespace

TEST(ImuDataset, RoundTripKeepsFieldsExtraColumnsAndFourDecimals) {
    const std::string dir = test::scratch_dir("imu_dataset_round");
    ImuRecording r;
    r.path = "s1/walk.csv";
    r.dataset = "toy";
    r.subject = "s1";
    r.activity = "walking";
    r.position = "waist";
    r.rate_hz = 50;
    r.extra = {{"trial", "3"}};
    r.t = {0, 0.02, 0.04};
    r.samples = {{0, 9.80666, -0.00001, 1, 2, 3}, {0.5, 9.8, 0, 1, 2, 3}, {1.23456, 9.8, 0, 1, 2, 3}};
    write_imu_dataset(dir, {r});
    EXPECT_EQ(
        read_file_text(dir + "/s1/walk.csv"),
        "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n0,0,9.8067,0,1,2,3\n0.02,0.5,9.8,0,1,2,3\n0.04,1.2346,9.8,0,1,2,3\n");
    const std::vector<ImuRecording> back = read_imu_dataset(dir);
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].activity, "walking");
    EXPECT_EQ(back[0].extra.at("trial"), "3");
    EXPECT_EQ(back[0].n_samples, 3u);
    EXPECT_DOUBLE_EQ(back[0].samples[2][0], 1.2346);
    EXPECT_EQ(read_imu_dataset(dir, false)[0].samples.size(), 0u);  // manifest only
    EXPECT_EQ(read_imu_dataset(dir, false)[0].n_samples, 3u);
}

TEST(ImuDataset, RecordingsOneAtATimeThenTheManifest) {
    const std::string dir = test::scratch_dir("imu_dataset_parts");
    const ImuSignals s = signals(5, 20);
    write_imu_recording(dir + "/a/waist.csv", s);
    // Six decimals, trailing zeros dropped; a negative that rounds to zero is written 0.
    EXPECT_NE(read_file_text(dir + "/a/waist.csv").find("\n0.05,0.05,-9.80665,0.333333,0,0,2.5\n"), std::string::npos);
    ImuRecording row;
    row.path = "a/waist.csv";
    row.dataset = "t2imu";
    row.subject = "body1";
    row.activity = "walking";
    row.position = "waist";
    row.rate_hz = 20;
    row.n_samples = 5;
    row.extra = {{"job", "j0"}, {"body", "body1"}, {"prompt", "walks"}};
    write_imu_manifest(dir, {row}, {"prompt", "body"});
    const CsvTable m = read_csv(dir + "/manifest.csv");
    EXPECT_EQ(m.header, (std::vector<std::string>{"path", "dataset", "subject", "activity", "position", "rate_hz",
                                                  "n_samples", "units", "prompt", "body", "job"}));
    const std::vector<ImuRecording> back = read_imu_dataset(dir);
    ASSERT_EQ(back.size(), 1u);
    EXPECT_NEAR(back[0].samples[4][2], 1.0 / 3.0, 1e-6);
    EXPECT_DOUBLE_EQ(back[0].samples[4][5], 2.5);

    row.n_samples = 6;  // the manifest promises more than the file holds
    write_imu_manifest(dir, {row});
    try {
        read_imu_dataset(dir);
        FAIL() << "a short recording was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("6 samples"), std::string::npos) << e.what();
    }
}

TEST(ImuDataset, RefusesAWrongHeaderAndNonFiniteValues) {
    const std::string dir = test::scratch_dir("imu_dataset_bad");
    write_imu_recording(dir + "/r.csv", signals(3, 10));
    ImuRecording row;
    row.path = "r.csv";
    row.rate_hz = 10;
    row.n_samples = 3;
    write_imu_manifest(dir, {row});
    write_file_atomic(dir + "/r.csv", "t,ax,ay,az,gx,gy,gz\n0,0,0,0,0,0,0\n0.1,0,0,0,0,0,0\n0.2,0,0,0,0,0,0\n");
    EXPECT_THROW(read_imu_dataset(dir), Error);
    write_file_atomic(dir + "/r.csv",
                      "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n0,0,0,0,0,0,0\n0.1,0,nan,0,0,0,0\n0.2,0,0,0,0,0,0\n");
    try {
        read_imu_dataset(dir);
        FAIL() << "a NaN was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("acc_y"), std::string::npos) << e.what();
    }
}

TEST(ImuDataset, HugeAndNonFiniteSamplesAreRefusedNamingFileRowAndColumnAndNothingIsWritten) {
    // A value of 1e43 once advanced the writer past its 48-byte buffer and wrote NUL and binary bytes into the CSV.
    const std::string dir = test::scratch_dir("imu_dataset_huge");
    const std::pair<double, const char*> bad[] = {
        {1e43, "acc_y"}, {1e300, "acc_y"}, {-1.5e6, "acc_y"}, {NAN, "acc_y"}, {INFINITY, "acc_y"}};
    for (const auto& [value, column] : bad) {
        ImuSignals s = signals(4, 10);
        s.acc[2].y() = value;
        const std::string m = test::error_message([&] { write_imu_recording(dir + "/r.csv", s); });
        EXPECT_TRUE(test::contains(m, dir + "/r.csv") && test::contains(m, "row 4") && test::contains(m, column)) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos);
        EXPECT_FALSE(std::ifstream(dir + "/r.csv").good());
    }
    ImuRecording r;
    r.path = "rec.csv";
    r.rate_hz = 10;
    r.t = {0, 0.1};
    r.samples = {{0, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 0, 2e7}};
    const std::string m = test::error_message([&] { write_imu_dataset(dir, {r}); });
    EXPECT_TRUE(test::contains(m, "rec.csv") && test::contains(m, "row 3") && test::contains(m, "gyr_z") &&
                test::contains(m, "2e+07"))
        << m;
    EXPECT_FALSE(std::ifstream(dir + "/manifest.csv").good());
}

TEST(ImuDataset, TheLargestAcceptedAndTiniestSamplesRoundTripAsText) {
    const std::string dir = test::scratch_dir("imu_dataset_extremes");
    ImuSignals s = signals(3, 10);
    s.acc[0] = Eigen::Vector3d(1e6, -1e6, 4.9e-324);  // the limits and a denormal (written as 0)
    s.gyr[1] = Eigen::Vector3d(-999999.999999, 1e-7, -1e-7);
    write_imu_recording(dir + "/r.csv", s);
    const std::string text = read_file_text(dir + "/r.csv");
    EXPECT_TRUE(test::contains(text, "1000000,-1000000,0,")) << text;
    EXPECT_TRUE(test::contains(text, "-999999.999999,0,0\n")) << text;  // 1e-7 below the 6th decimal: "0", never "-0"
    EXPECT_FALSE(test::contains(text, "-0,") || test::contains(text, "-0\n")) << text;
    for (char c : text) EXPECT_TRUE(c == '\n' || (c >= ' ' && c <= '~')) << static_cast<int>(c);
}
