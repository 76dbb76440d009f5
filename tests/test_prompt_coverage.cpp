// Prompt coverage on a made-up vocabulary and caption set: a known activity with its nearest captions, an
// activity with no captions ("ironing"), a prompt naming no activity, and attribute words the captions of the
// activity never use (slowly) against ones they do (left); and docs/coverage.md against the shipped model's captions.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "core/error.hpp"
#include "test_util.hpp"
#include "text/prompt_coverage.hpp"

using namespace t2imu;

namespace {

WordVectors vocabulary() {
    return test::axis_vocabulary({{"walks", {1, 0, 0, 0}},
                                  {"left", {0, 1, 0, 0}},
                                  {"slowly", {0, 0, 1, 0}},
                                  {"runs", {0, 0, 0, 1}},
                                  {"irons", {0.5f, 0.5f, 0.5f, 0}}});
}

}  // namespace

TEST(PromptCoverage, AKnownActivityWithAttributesItsCaptionsNameIsCovered) {
    const WordVectors vocab = vocabulary();
    const CaptionIndex index(vocab, {{"walking", "walks"}, {"walking", "walks left"}, {"running", "runs slowly"}},
                             "captions.tsv");
    const PromptCoverage c = prompt_coverage(index, "walking", "walks left");
    EXPECT_TRUE(c.activity_known);
    EXPECT_TRUE(c.covered());
    ASSERT_EQ(c.nearest.size(), 2u);
    EXPECT_EQ(c.nearest[0], "walks left");
    EXPECT_GT(c.similarity[0], c.similarity[1]);
    EXPECT_EQ(c.summary(), "covered");
}

TEST(PromptCoverage, AnAttributeOnlyAnotherActivitysCaptionsNameIsUncovered) {
    const WordVectors vocab = vocabulary();
    const CaptionIndex index(vocab, {{"walking", "walks"}, {"walking", "walks left"}, {"running", "runs slowly"}},
                             "captions.tsv");
    const PromptCoverage c = prompt_coverage(index, "walking", "walks slowly");
    EXPECT_TRUE(c.activity_known);
    EXPECT_FALSE(c.covered());
    EXPECT_EQ(c.attributes_uncovered, std::vector<std::string>{"pace_slow"});
    EXPECT_EQ(c.summary(), "the training captions of 'walking' never name: pace_slow");
}

TEST(PromptCoverage, AnActivityWithoutCaptionsOrNoneAtAllIsUncovered) {
    const WordVectors vocab = vocabulary();
    const CaptionIndex index(vocab, {{"walking", "walks"}, {"running", "runs"}}, "captions.tsv");
    const PromptCoverage ironing = prompt_coverage(index, "ironing", "irons a shirt");
    EXPECT_EQ(ironing.activity, "ironing");
    EXPECT_FALSE(ironing.activity_known);
    EXPECT_FALSE(ironing.covered());
    EXPECT_EQ(ironing.summary(), "activity 'ironing' has no training captions");
    const PromptCoverage none = prompt_coverage(index, "", "irons a shirt");
    EXPECT_FALSE(none.covered());
    EXPECT_EQ(none.summary(), "names no activity the model knows");
}

TEST(PromptCoverage, CheckingASetWarnsOrWithRequireRefusesTheFirstUncoveredPrompt) {
    const WordVectors vocab = vocabulary();
    const CaptionIndex index(vocab, {{"walking", "walks"}, {"walking", "walks left"}}, "captions.tsv");
    const std::vector<Prompt> prompts = {{"walking", "walks left"}, {"walking", "walks slowly"}, {"ironing", "irons"}};
    const std::vector<PromptCoverage> c = check_prompts_covered(index, prompts, "p.tsv", false);
    ASSERT_EQ(c.size(), 3u);
    EXPECT_TRUE(c[0].covered());
    EXPECT_FALSE(c[1].covered());
    EXPECT_FALSE(c[2].covered());
    try {
        check_prompts_covered(index, prompts, "p.tsv", true);
        ADD_FAILURE() << "an uncovered prompt passed with require";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "p.tsv: prompt 2: --require-coverage: expected a prompt the model's training captions cover (got the "
                  "training captions of 'walking' never name: pace_slow)");
    }
}

TEST(PromptCoverage, DocsCoverageIsWhatTheShippedModelsCaptionsCover) {
    // docs/coverage.md is made by `t2imu text coverage --model models/default`: it must follow the model's captions.
    const std::string root = T2IMU_SOURCE_DIR;
    const std::vector<Prompt> captions =
        read_prompt_set(root + "/models/default/captions.tsv", PromptActivity::required);
    std::ifstream in(root + "/docs/coverage.md");
    const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(doc, coverage_markdown(captions, "models/default"))
        << "remake it: build/t2imu text coverage --model models/default --out docs/coverage.md";
}
