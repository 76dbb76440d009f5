// Caption augmentation on a tiny vocabulary whose geometry is known: "walks" has "strolls" (cosine 0.98) and
// "walking" (0.92) near it and "runs" (0.88) beyond the similarity floor of 0.9; "person" and "man" are near
// each other (0.995).
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "test_util.hpp"
#include "text/caption_augment.hpp"

namespace t2imu {
namespace {

WordVectors tiny_vocabulary() {
    // 2-d directions padded to 100 dimensions: the cosine of two words is the cosine of their angles.
    const std::vector<std::pair<std::string, double>> words = {{"a", 3.0},     {"person", 1.0},  {"man", 1.1},
                                                               {"walks", 0.0}, {"strolls", 0.2}, {"walking", -0.4},
                                                               {"runs", 0.5},  {".", 2.5}};
    std::vector<std::string> names;
    std::vector<float> v;
    for (const auto& [w, angle] : words) {
        names.push_back(w);
        std::vector<float> row(WordVectors::kDims, 0.0f);
        row[0] = static_cast<float>(std::cos(angle));
        row[1] = static_cast<float>(std::sin(angle));
        v.insert(v.end(), row.begin(), row.end());
    }
    return WordVectors(names, v);
}

TEST(CaptionAugment, NeighboursAreTheNearestWordsAboveTheFloor) {
    const WordVectors vocab = tiny_vocabulary();
    CaptionAugmentOptions o;
    o.swap = 0.5;
    o.neighbours = 3;
    o.min_similarity = 0.9;
    CaptionAugmenter a(vocab, o, {"A person walks."});
    std::vector<std::string> near;
    for (int w : a.neighbours_of(vocab.index_of("walks"))) near.push_back(vocab.word(w));
    EXPECT_EQ(near, (std::vector<std::string>{"strolls", "walking"}));  // cos 0.2 = 0.98, cos 0.4 = 0.92; runs 0.5
    std::vector<std::string> person;
    for (int w : a.neighbours_of(vocab.index_of("person"))) person.push_back(vocab.word(w));
    EXPECT_EQ(person, (std::vector<std::string>{"man"}));
}

TEST(CaptionAugment, OffLeavesTheTokensAndFullSwapRewordsEveryWordWithNeighbours) {
    const WordVectors vocab = tiny_vocabulary();
    std::mt19937_64 rng(1);
    CaptionAugmentOptions off;
    CaptionAugmenter same(vocab, off, {});
    EXPECT_EQ(same.augment("A person walks.", rng), "a person walks .");
    CaptionAugmentOptions all;
    all.swap = 0.999999;
    all.min_similarity = 0.9;
    CaptionAugmenter reword(vocab, all, {"A person walks."});
    for (int i = 0; i < 20; ++i) {
        const std::string out = reword.augment("A person walks.", rng);
        EXPECT_TRUE(out == "a man strolls ." || out == "a man walking .") << out;
    }
    // The same seed gives the same rewording.
    std::mt19937_64 r1(7), r2(7);
    EXPECT_EQ(reword.augment("A person walks.", r1), reword.augment("A person walks.", r2));
}

TEST(CaptionAugment, DirectionsAndTheActivityAreKept) {
    // "up" and "down" are neighbours (cosine 0.999), as are "walks" and "runs": a swap may not turn a climb into
    // a descent or a walk into a run; "person" has no neighbour above 0.9.
    const WordVectors vocab({"a", "person", "walks", "runs", "up", "down", "stairs"}, [] {
        std::vector<float> v(7 * WordVectors::kDims, 0.0f);
        const double angles[] = {3.0, 1.5, 0.0, 0.05, -1.0, -1.05, 2.2};
        for (int w = 0; w < 7; ++w) {
            v[static_cast<size_t>(w) * WordVectors::kDims] = static_cast<float>(std::cos(angles[w]));
            v[static_cast<size_t>(w) * WordVectors::kDims + 1] = static_cast<float>(std::sin(angles[w]));
        }
        return v;
    }());
    CaptionAugmentOptions o;
    o.swap = 0.999999;
    o.min_similarity = 0.9;
    CaptionAugmenter a(vocab, o, {});
    std::mt19937_64 rng(5);
    for (int i = 0; i < 10; ++i) {
        EXPECT_EQ(a.augment("a person walks", rng), "a person walks");      // "runs" would name another activity
        EXPECT_EQ(a.augment("a person goes up", rng), "a person goes up");  // "up" never becomes "down"
    }
}

TEST(CaptionAugment, DropoutNeverLeavesNoWord) {
    const WordVectors vocab = tiny_vocabulary();
    CaptionAugmentOptions o;
    o.dropout = 0.999999;
    CaptionAugmenter a(vocab, o, {});
    std::mt19937_64 rng(3);
    EXPECT_EQ(a.augment("A person walks.", rng), "A person walks.");
    o.dropout = 0.5;
    CaptionAugmenter half(vocab, o, {});
    int shorter = 0;
    for (int i = 0; i < 50; ++i) {
        const std::string out = half.augment("a person walks", rng);
        EXPECT_TRUE(test::contains(out, "walks")) << out;  // dropping the activity's word would unname it
        shorter += out != "a person walks";
    }
    EXPECT_GT(shorter, 10);  // "walks" kept (1/2) and "a" or "person" dropped (3/4): 3 in 8
}

TEST(CaptionAugment, RefusesOptionsOutOfRangeByKey) {
    CaptionAugmentOptions o;
    o.swap = 1.0;
    EXPECT_TRUE(test::contains(test::error_message([&] { o.validate("c.toml"); }), "augment.swap"));
    o = {};
    o.neighbours = 0;
    EXPECT_TRUE(test::contains(test::error_message([&] { o.validate("c.toml"); }), "augment.neighbours"));
    o = {};
    o.min_similarity = 1.0;
    EXPECT_TRUE(test::contains(test::error_message([&] { o.validate("c.toml"); }), "augment.min_similarity"));
}

}  // namespace
}  // namespace t2imu
