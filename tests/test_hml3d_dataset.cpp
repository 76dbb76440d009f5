// The batch loader on a small folder in the official HumanML3D layout, written here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "core/npy.hpp"
#include "data/hml3d_dataset.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

// Clip "a": 120 frames, whole caption + a span 1.0-4.0 s; "b": 30 frames (too short, dropped);
// "c": 250 frames (too long as a whole; its 2.0-8.0 s span is kept). Feature value = 1000 * clip + frame.
std::string make_official_layout(const std::string& name) {
    const std::string dir = test::scratch_dir(name);
    std::filesystem::create_directories(dir + "/new_joint_vecs");
    std::filesystem::create_directories(dir + "/texts");
    auto motion = [&](const std::string& id, int frames, int base) {
        std::vector<float> v(static_cast<size_t>(frames) * 263);
        for (int t = 0; t < frames; ++t)
            for (int c = 0; c < 263; ++c)
                v[static_cast<size_t>(t) * 263 + static_cast<size_t>(c)] = static_cast<float>(base + t);
        write_npy(dir + "/new_joint_vecs/" + id + ".npy", NdArray::from(v, {frames, 263}));
    };
    motion("a", 120, 1000);
    motion("b", 30, 2000);
    motion("c", 250, 3000);
    std::ofstream(dir + "/texts/a.txt") << "a person walks#a/DET person/NOUN walk/VERB#0.0#0.0\nthen stops##1.0#4.0\n";
    std::ofstream(dir + "/texts/b.txt") << "short##0.0#0.0\n";
    std::ofstream(dir + "/texts/c.txt") << "long##0.0#0.0\nmiddle part##2.0#8.0\n";
    std::ofstream(dir + "/train.txt") << "a\nb\nc\nmissing\n";
    write_npy(dir + "/Mean.npy", NdArray::from(std::vector<float>(263, 100.f), {263}));
    write_npy(dir + "/Std.npy", NdArray::from(std::vector<float>(263, 2.f), {263}));
    return dir;
}

}  // namespace

TEST(Hml3dDataset, OfficialRulesForClipsAndSpans) {
    Hml3dDataset d(make_official_layout("hml3d_layout_rules"), "train");
    std::map<std::string, Eigen::Index> frames;
    for (const MotionClip& c : d.clips()) frames[c.id] = c.features.rows();
    EXPECT_EQ(frames.size(), 3u);
    EXPECT_EQ(frames["a"], 120);
    EXPECT_EQ(frames["a#20-80"], 60);
    EXPECT_EQ(frames["c#40-160"], 120);
    EXPECT_EQ(d.skipped_ids(), 2);  // b (too short) and the missing id; c is used through its span
}

TEST(Hml3dDataset, BatchesAreCroppedNormalisedPaddedAndSeeded) {
    const std::string dir = make_official_layout("hml3d_layout_batches");
    Hml3dDataset d(dir, "train");
    d.seed(7);
    std::set<std::string> epoch;
    for (int k = 0; k < 3; ++k) {
        const Batch b = d.next_batch(1);
        epoch.insert(b.ids[0]);
    }
    EXPECT_EQ(epoch.size(), 3u);  // one epoch visits every clip once

    d.seed(11);
    const Batch b = d.next_batch(16);
    for (int i = 0; i < b.size; ++i) {
        const int len = b.lengths[static_cast<size_t>(i)];
        EXPECT_EQ(len % 4, 0);
        EXPECT_GE(len, 40 - 4);
        EXPECT_LE(len, 196);
        for (int t = 0; t < 196; ++t) {
            const uint8_t m = b.mask[static_cast<size_t>(i) * 196 + static_cast<size_t>(t)];
            EXPECT_EQ(m, t < len ? 1 : 0);
        }
        // Normalised (x - 100) / 2 with x = base + frame: consecutive frames differ by 0.5; padding is 0.
        const float* row = &b.features[static_cast<size_t>(i) * 196 * 263];
        EXPECT_FLOAT_EQ(row[263] - row[0], 0.5f);
        EXPECT_EQ(row[static_cast<size_t>(len) * 263], 0.0f);
    }
    d.seed(11);
    const Batch again = d.next_batch(16);
    EXPECT_EQ(again.features, b.features);
    EXPECT_EQ(again.captions, b.captions);
}
