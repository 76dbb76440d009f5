// The shipped prompt set: ten distinct prompts for each RealWorld class, and what they say is what the
// caption categoriser (SIF over GloVe) reads in them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "analysis/activity_categories.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {
std::vector<std::pair<std::string, std::string>> shipped_prompts() {
    std::ifstream in(test::source_dir() + "/prompts/realworld.tsv");
    std::vector<std::pair<std::string, std::string>> out;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        const size_t tab = line.find('\t');
        out.push_back({line.substr(0, tab), line.substr(tab + 1)});
    }
    return out;
}
}  // namespace

TEST(Prompts, TenDistinctPromptsPerRealWorldClass) {
    std::map<std::string, std::set<std::string>> by_class;
    for (const auto& [activity, prompt] : shipped_prompts()) by_class[activity].insert(prompt);
    const std::set<std::string> classes = {"walking", "running", "jumping", "sitting", "standing", "lying", "stairs_up", "stairs_down"};
    ASSERT_EQ(by_class.size(), classes.size());
    for (const auto& [activity, prompts] : by_class) {
        EXPECT_TRUE(classes.count(activity)) << activity;
        EXPECT_EQ(prompts.size(), 10u) << activity;
    }
}

TEST(Prompts, TheCategoriserReadsTheirActivity) {
    const std::string vocab = test::source_dir() + "/cache/text/glove-100k.safetensors";
    if (!std::filesystem::exists(vocab)) GTEST_SKIP() << "cache/text/glove-100k.safetensors absent (scripts/setup.sh makes it)";
    const WordVectors v = WordVectors::load(vocab);
    const SifEncoder sif(v, kCategorySifWeight);
    const ActivityCategorizer categorizer(sif, 0.0);  // nearest category, no Other
    const std::map<std::string, std::string> category = {{"walking", "Walking"}, {"running", "Running"}, {"jumping", "Jumping"},
                                                         {"sitting", "Sitting"}, {"standing", "Standing"}, {"lying", "Lying"},
                                                         {"stairs_up", "Stair climbing"}, {"stairs_down", "Stair climbing"}};
    int agree = 0, total = 0;
    for (const auto& [activity, prompt] : shipped_prompts()) {
        agree += categorizer.categorize(prompt).category == category.at(activity);
        ++total;
    }
    std::printf("%d of %d prompts categorised as their activity\n", agree, total);
    EXPECT_GE(agree, total * 7 / 10);
}
