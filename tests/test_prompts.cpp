// The shipped prompt set: ten distinct prompts for each RealWorld class, and what they say is what the
// caption categoriser (SIF over GloVe) reads in them.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>

#include "analysis/activity_categories.hpp"
#include "har/class_map.hpp"
#include "test_util.hpp"
#include "text/prompt_set.hpp"

using namespace t2imu;

namespace {
std::vector<std::pair<std::string, std::string>> shipped_prompts(const std::string& set = "realworld") {
    std::vector<std::pair<std::string, std::string>> out;
    for (const Prompt& p : read_prompt_set(test::source_dir() + "/prompts/" + set + ".tsv"))
        out.push_back({p.activity, p.text});
    return out;
}

// Ten distinct prompts for each of `classes`, and no other class.
void expect_ten_per_class(const std::string& set, const std::set<std::string>& classes) {
    std::map<std::string, std::set<std::string>> by_class;
    for (const auto& [activity, prompt] : shipped_prompts(set)) by_class[activity].insert(prompt);
    EXPECT_EQ(by_class.size(), classes.size()) << set;
    for (const auto& [activity, prompts] : by_class) {
        EXPECT_TRUE(classes.count(activity)) << set << ": " << activity;
        EXPECT_EQ(prompts.size(), 10u) << set << ": " << activity;
    }
}
}  // namespace

TEST(Prompts, TenDistinctPromptsPerRealWorldClass) {
    expect_ten_per_class("realworld",
                         {"walking", "running", "jumping", "sitting", "standing", "lying", "stairs_up", "stairs_down"});
}

// The paraphrase set (issue 25: text conditioning on unseen wording): the same classes, ten each, none of them a
// prompt of the main set, and none in the captions' stock opening "a person".
TEST(Prompts, ParaphraseSetIsFreshWordingForTheSameClasses) {
    expect_ten_per_class("paraphrase",
                         {"walking", "running", "jumping", "sitting", "standing", "lying", "stairs_up", "stairs_down"});
    std::set<std::string> main_set;
    for (const auto& [activity, prompt] : shipped_prompts()) main_set.insert(prompt);
    for (const auto& [activity, prompt] : shipped_prompts("paraphrase")) {
        EXPECT_FALSE(main_set.count(prompt)) << prompt;
        EXPECT_NE(prompt.rfind("A person", 0), 0u) << prompt;
        EXPECT_NE(prompt.rfind("The person", 0), 0u) << prompt;
    }
}

// The real data sets' prompt sets use their own class names (as in their manifests), which the class map
// then treats as it treats the real recordings.
TEST(Prompts, RealDataSetsPromptSetsUseTheirOwnClassNames) {
    expect_ten_per_class("sisfall", {"walking", "jogging", "stairs_up_down", "sit_down_stand_up", "lying"});
    expect_ten_per_class("umafall", {"walking", "jogging", "jumping", "stairs_up", "stairs_down", "sit_down_stand_up",
                                     "lie_down_get_up_bed", "bending", "hands_up", "applauding"});
    for (const auto& [activity, prompt] : shipped_prompts("sisfall"))
        EXPECT_EQ(map_activity("t2imu", activity), map_activity("sisfall", activity));
    for (const auto& [activity, prompt] : shipped_prompts("umafall"))
        EXPECT_EQ(map_activity("t2imu", activity), map_activity("umafall", activity));
}

TEST(Prompts, TheCategoriserReadsTheirActivity) {
    const std::string vocab = test::source_dir() + "/cache/text/glove-100k.safetensors";
    if (!std::filesystem::exists(vocab))
        GTEST_SKIP() << "cache/text/glove-100k.safetensors absent (scripts/setup.sh makes it)";
    const WordVectors v = WordVectors::load(vocab);
    const SifEncoder sif(v, kCategorySifWeight);
    const ActivityCategorizer categorizer(sif, 0.0);  // nearest category, no Other
    const std::map<std::string, std::string> category = {
        {"walking", "Walking"},          {"running", "Running"},           {"jumping", "Jumping"},
        {"sitting", "Sitting"},          {"standing", "Standing"},         {"lying", "Lying"},
        {"stairs_up", "Stair climbing"}, {"stairs_down", "Stair climbing"}};
    int agree = 0, total = 0;
    for (const auto& [activity, prompt] : shipped_prompts()) {
        agree += categorizer.categorize(prompt).category == category.at(activity);
        ++total;
    }
    std::printf("%d of %d prompts categorised as their activity\n", agree, total);
    EXPECT_GE(agree, total * 7 / 10);
}

// What a prompts file may hold: a byte-order mark is dropped (it once became part of the first activity label);
// blank prompts and activities, bidi controls and control bytes are refused naming the line; a file that never
// ends is refused after its cap instead of filling memory.
TEST(Prompts, ByteOrderMarkBlankTextBidiControlsAndEndlessFiles) {
    const std::vector<Prompt> p =
        parse_prompt_set("\xEF\xBB\xBFwalking\ta person walks\n", "p.tsv", PromptActivity::required);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].activity, "walking");
    const std::pair<const char*, const char*> bad[] = {
        {"walking\t   \n", "not blank"},
        {"   \ta person walks\n", "not blank"},
        {"walking\ta person \xE2\x80\xAEsklaw\n", "U+202E"},
        {"walking\ta person\xE2\x81\xA6 walks\n", "U+2066"},
        {"walking\ta person \x1b[31mwalks\n", "U+001B"},
    };
    for (const auto& [text, why] : bad) {
        const std::string m = test::error_message(
            [&] { parse_prompt_set(std::string("# set\n") + text, "p.tsv", PromptActivity::required); });
        EXPECT_TRUE(test::contains(m, "p.tsv: line 2") && test::contains(m, why)) << m;
    }
    if (!std::filesystem::exists("/dev/zero")) GTEST_SKIP() << "no /dev/zero";
    const std::string m = test::error_message([] { read_prompt_set("/dev/zero"); });
    EXPECT_TRUE(test::contains(m, "/dev/zero: size") && test::contains(m, "16 MiB")) << m;
}
