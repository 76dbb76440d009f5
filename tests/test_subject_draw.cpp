// har/subject_draw: the seeded subject draw, the refusals before training, and the batch shares.
#include "har/subject_draw.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

std::vector<std::string> subjects_of(int n) {
    std::vector<std::string> s;
    for (int i = 0; i < n; ++i)
        for (int repeat = 0; repeat < 3; ++repeat) s.push_back("S" + std::to_string(10 + i));  // one id per window
    return s;
}

}  // namespace

TEST(SubjectDraw, SeededSortedAndDifferentPerRepeat) {
    const std::vector<std::string> all = subjects_of(12);
    const std::vector<std::string> a = draw_subjects(all, 4, 7, 0), again = draw_subjects(all, 4, 7, 0);
    EXPECT_EQ(a, again);  // the same seed and repeat: the same subjects
    ASSERT_EQ(a.size(), 4u);
    EXPECT_TRUE(std::is_sorted(a.begin(), a.end()));
    EXPECT_EQ(std::set<std::string>(a.begin(), a.end()).size(), 4u);
    std::set<std::vector<std::string>> draws;
    for (int repeat = 0; repeat < 6; ++repeat) draws.insert(draw_subjects(all, 4, 7, repeat));
    EXPECT_GE(draws.size(), 5u);  // 495 possible draws of 4 of 12: six repeats all but never coincide
    EXPECT_NE(draw_subjects(all, 4, 8, 0), a);
    EXPECT_TRUE(draw_subjects(all, 0, 7, 0).empty());
    EXPECT_EQ(draw_subjects(all, 11, 7, 3).size(), 11u);  // one subject left to test on
}

TEST(SubjectDraw, RefusesWhatCannotBeDrawn) {
    const std::vector<std::string> all = subjects_of(3);
    EXPECT_TRUE(test::contains(test::error_message([&] { draw_subjects(all, 3, 0, 0); }),
                               "--train-subjects: 3: expected from 0 to 2"));
    EXPECT_TRUE(test::contains(test::error_message([&] { draw_subjects(all, -1, 0, 0); }), "--train-subjects"));
    std::vector<std::string> unnamed = all;
    unnamed.push_back("");
    EXPECT_TRUE(
        test::contains(test::error_message([&] { draw_subjects(unnamed, 1, 0, 0); }), "recordings name their subject"));
    EXPECT_TRUE(test::contains(test::error_message([&] {
                                   draw_subjects({"sisfall:SA01", "sisfall:"}, 1, 0, 0);
                               }),
                               "recordings name their subject"));
}

TEST(SubjectDraw, SplitRefusesATestSubjectInATrainingSet) {
    const std::vector<std::string> real = {"SA01", "SA02", "SA03"}, synthetic = {"male_average", "female_tall"};
    EXPECT_NO_THROW(check_subject_split({synthetic, real}, {"syn", "real"}, real, 1, 2));
    const std::string e = test::error_message([&] {
        check_subject_split({synthetic, {"SA02"}}, {"syn", "other"}, real, -1, 0);
    });
    EXPECT_TRUE(test::contains(e, "--train: other: expected no subject of the --test set (SA02 is in both")) << e;
    // The same folder as training and test set without a draw: every subject is in both.
    EXPECT_TRUE(test::contains(test::error_message([&] { check_subject_split({real}, {"real"}, real, -1, 0); }),
                               "SA01 is in both"));
    EXPECT_TRUE(test::contains(test::error_message([&] {
                                   check_subject_split({synthetic, real}, {"syn", "real"}, real, 1, 3);
                               }),
                               "at least one is left to test on"));
}

TEST(SubjectDraw, SharesAreHonouredToWithinOneWindow) {
    const std::vector<double> shares = {0.7, 0.3};
    const std::vector<size_t> windows = {5000, 800};
    const auto batches = batch_counts(shares, windows, 64);
    // The epoch: 800 / 0.3 = 2666 windows, cut into whole batches of 64 (41 batches, 2624 windows).
    ASSERT_EQ(batches.size(), 41u);
    size_t total = 0, first = 0;
    for (const auto& b : batches) {
        EXPECT_EQ(b[0] + b[1], 64u);
        total += 64, first += b[0];
        EXPECT_LE(std::abs(static_cast<double>(first) - 0.7 * static_cast<double>(total)), 0.5);  // after every batch
    }
    EXPECT_LE(total - first, 800u);  // no set used up within the epoch
    // Three sets, one small share: every batch is full and each set stays within one window of its share.
    const auto three = batch_counts({0.5, 0.45, 0.05}, {1000, 1000, 1000}, 20);
    size_t seen = 0;
    std::vector<size_t> sum(3, 0);
    for (const auto& b : three) {
        seen += b[0] + b[1] + b[2];
        for (size_t i = 0; i < 3; ++i) sum[i] += b[i];
        EXPECT_EQ(b[0] + b[1] + b[2], 20u);
        for (size_t i = 0; i < 3; ++i)
            EXPECT_LE(std::abs(static_cast<double>(sum[i]) -
                               std::vector<double>{0.5, 0.45, 0.05}[i] * static_cast<double>(seen)),
                      1.0);
    }
    EXPECT_EQ(seen, 2000u);                                        // 1000 / 0.5
    EXPECT_EQ(batch_counts({0.5, 0.5}, {10, 40}, 64).size(), 1u);  // shorter than a batch: one short batch of 20
}

TEST(SubjectDraw, SharesAreCheckedBeforeTraining) {
    EXPECT_NO_THROW(check_shares({}, 2, 64, "--train-share"));
    EXPECT_NO_THROW(check_shares({0.25, 0.75}, 2, 64, "--train-share"));
    EXPECT_TRUE(test::contains(test::error_message([] { check_shares({0.5}, 2, 64, "--train-share"); }),
                               "2 shares, one per --train"));
    EXPECT_TRUE(test::contains(test::error_message([] {
                                   check_shares({0.5, 0.6}, 2, 64, "--train-share");
                               }),
                               "add up to 1"));
    EXPECT_TRUE(test::contains(test::error_message([] {
                                   check_shares({0.995, 0.005}, 2, 64, "--train-share");
                               }),
                               "at least one window"));
    EXPECT_TRUE(test::contains(test::error_message([] {
                                   check_shares({1.5, -0.5}, 2, 64, "--train-share");
                               }),
                               "--train-share"));
}
