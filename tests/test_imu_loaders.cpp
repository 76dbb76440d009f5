// Release-format loaders reproduce the shared compact copies from the raw samples those were made from.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "har/datasets/hugadb.hpp"
#include "har/datasets/sisfall.hpp"
#include "har/datasets/umafall.hpp"
#include "imu/imu_dataset.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

// Every recording of `ours` equals the compact copy's recording of the same path (values written with 4
// decimals there, so within 0.5e-4 plus rounding).
void expect_matches_compact(const std::vector<ImuRecording>& ours, const std::string& compact_dir, size_t expected) {
    std::map<std::string, ImuRecording> theirs;
    for (ImuRecording& r : read_imu_dataset(compact_dir)) theirs[r.path] = std::move(r);
    size_t matched = 0;
    for (const ImuRecording& r : ours) {
        const auto it = theirs.find(r.path);
        ASSERT_NE(it, theirs.end()) << "not in the compact copy: " << r.path;
        const ImuRecording& c = it->second;
        EXPECT_EQ(c.activity, r.activity);
        EXPECT_EQ(c.position, r.position);
        EXPECT_NEAR(c.rate_hz, r.rate_hz, 1e-9);
        ASSERT_EQ(c.samples.size(), r.samples.size()) << r.path;
        double worst = 0;
        for (size_t i = 0; i < r.samples.size(); ++i) {
            worst = std::max(worst, std::fabs(c.t[i] - r.t[i]));
            for (size_t k = 0; k < 6; ++k) worst = std::max(worst, std::fabs(c.samples[i][k] - r.samples[i][k]));
        }
        EXPECT_LT(worst, 0.5e-4 + 1e-9) << r.path;
        ++matched;
    }
    EXPECT_EQ(matched, expected);
}

}  // namespace

TEST(ImuLoaders, HuGaDBRawSampleReproducesTheCompactCopy) {
    std::string raw;
    SHARED_OR_SKIP(raw, "imu/hugadb/raw-sample");
    const std::vector<ImuRecording> ours = import_hugadb(raw);
    EXPECT_EQ(ours.size(), 12u);  // 2 files x 6 IMUs, walking only
    expect_matches_compact(ours, test::unpacked_shared_archive("imu/hugadb/hugadb.tar.xz"), 12);
}

TEST(ImuLoaders, UMAFallRawSampleReproducesTheCompactCopy) {
    std::string raw;
    SHARED_OR_SKIP(raw, "imu/umafall/raw-sample");
    std::vector<std::string> skipped;
    const std::vector<ImuRecording> ours = import_umafall(raw, &skipped);
    EXPECT_TRUE(skipped.empty());
    ASSERT_EQ(ours.size(), 4u);  // ankle, waist, chest, wrist
    expect_matches_compact(ours, test::unpacked_shared_archive("imu/umafall/umafall.tar.xz"), 4);
    for (const ImuRecording& r : ours)
        EXPECT_EQ(r.extra.at("gyro_flag"), r.position == "ankle" ? "clipped" : "ok") << r.position;
}

TEST(ImuLoaders, SisFallRawSamplesReproduceTheCompactCopy) {
    // 200 -> 50 Hz through resample_poly: agreement with scipy's output, rounded to 3 (acc) and 4 (gyro) decimals.
    std::string raw;
    SHARED_OR_SKIP(raw, "imu/sisfall/raw-sample");
    std::vector<std::string> skipped;
    const std::vector<ImuRecording> ours = import_sisfall(raw, &skipped);
    ASSERT_EQ(ours.size(), 2u);  // D05 (stairs_up_down) and D19 (jump_reach)
    std::map<std::string, ImuRecording> theirs;
    for (ImuRecording& r : read_imu_dataset(test::unpacked_shared_archive("imu/sisfall/sisfall.tar.xz")))
        theirs[r.path] = std::move(r);
    for (const ImuRecording& r : ours) {
        ASSERT_TRUE(theirs.count(r.path)) << r.path;
        const ImuRecording& c = theirs[r.path];
        ASSERT_EQ(c.samples.size(), r.samples.size());
        double acc = 0, gyr = 0;
        for (size_t i = 0; i < r.samples.size(); ++i)
            for (size_t k = 0; k < 6; ++k)
                (k < 3 ? acc : gyr) = std::max(k < 3 ? acc : gyr, std::fabs(c.samples[i][k] - r.samples[i][k]));
        EXPECT_LT(acc, 0.5e-3 + 1e-9) << r.path;
        EXPECT_LT(gyr, 0.5e-4 + 1e-9) << r.path;
    }
}

TEST(ImuLoaders, RestingAccelerationIsGravity) {
    // UMAFall's sit-down/stand-up and lie-down trials rest most of the time: the median |acc| is about g.
    std::string archive;
    SHARED_OR_SKIP(archive, "imu/umafall/umafall.tar.xz");
    const std::string dir = test::unpacked_shared_archive("imu/umafall/umafall.tar.xz");
    std::vector<double> norms;
    for (const ImuRecording& r : read_imu_dataset(dir))
        if (r.activity == "sit_down_stand_up" && r.position == "chest")
            for (const auto& s : r.samples) norms.push_back(std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]));
    ASSERT_GT(norms.size(), 1000u);
    std::nth_element(norms.begin(), norms.begin() + static_cast<long>(norms.size() / 2), norms.end());
    EXPECT_NEAR(norms[norms.size() / 2], 9.81, 0.4);
}

TEST(ImuDataset, WriteThenReadRoundTrip) {
    ImuRecording r;
    r.path = "synthetic/s1/walking_0_seg0_left_thigh.csv";
    r.dataset = "synthetic";
    r.subject = "s1";
    r.activity = "walking";
    r.position = "left_thigh";
    r.rate_hz = 50;
    r.extra["prompt"] = "The person is walking slowly, with multiple strides.";
    for (int i = 0; i < 5; ++i) {
        r.t.push_back(i / 50.0);
        r.samples.push_back({0.1 * i, 9.81, -0.00004, 1.23456, 0, -2});
    }
    const std::string dir = test::scratch_dir("imu_dataset_roundtrip");
    write_imu_dataset(dir, {r});
    const std::vector<ImuRecording> back = read_imu_dataset(dir);
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].extra.at("prompt"), r.extra.at("prompt"));
    EXPECT_EQ(back[0].samples.size(), 5u);
    EXPECT_DOUBLE_EQ(back[0].samples[3][3], 1.2346);  // 4 decimals
    EXPECT_DOUBLE_EQ(back[0].samples[3][2], 0.0);     // -0.00004 is written as 0, not -0
    EXPECT_DOUBLE_EQ(back[0].t[4], 0.08);
}

TEST(ImuLoaders, CliImportWritesAReadableDataset) {
    std::string raw;
    SHARED_OR_SKIP(raw, "imu/hugadb/raw-sample");
    const std::string out = test::scratch_dir("import_imu_cli") + "/hugadb";
    const auto r = test::run_cli("data import-imu --format hugadb '" + raw + "' --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::vector<ImuRecording> back = read_imu_dataset(out);
    ASSERT_EQ(back.size(), 12u);
    EXPECT_EQ(back[0].extra.at("gyro_flag"), "unknown");
    EXPECT_EQ(test::run_cli("data import-imu --format pamap2 '" + raw + "' --out " + out).exit_code, 2);
}
