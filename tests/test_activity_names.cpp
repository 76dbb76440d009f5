// The activity vocabulary: data-set labels and the words of prompts name the same canonical activities.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "motion/activity_names.hpp"
#include "test_util.hpp"

namespace t2imu {
namespace {

TEST(ActivityNames, DataSetLabelsBecomeCanonicalNames) {
    EXPECT_EQ(canonical_activity("jogging"), "running");
    EXPECT_EQ(canonical_activity("sit_down_stand_up"), "sitting");
    EXPECT_EQ(canonical_activity("lie_down_get_up_bed"), "lying");
    EXPECT_EQ(canonical_activity("stairs_up_down"), "stairs");
    EXPECT_EQ(canonical_activity("climbingup"), "stairs_up");
    EXPECT_EQ(canonical_activity("walking"), "walking");
    EXPECT_EQ(canonical_activity("applauding"), "applauding");  // no alias: unchanged
}

TEST(ActivityNames, SynonymsAndPhrasesNameTheActivity) {
    const std::map<std::string, std::string> cases = {
        {"Someone sprints forward as fast as possible.", "running"},
        {"The person trots forward for several steps.", "running"},  // steps without a direction: not stairs
        {"A person jogs quickly down a hallway.", "running"},        // down without a stair word: not stairs
        {"A man runs straight ahead with big strides.", "running"},  // strides belong to the run
        {"A woman walks up several steps.", "stairs_up"},
        {"A person climbs down a staircase.", "stairs_down"},
        {"A person is climbing stairs.", "stairs_up"},
        {"Someone goes upstairs and then walks back downstairs.", "stairs"},
        {"The person ascends the stairs slowly.", "stairs_up"},
        {"A man sits down on a chair and then stands up.", "sitting"},
        {"Someone is seated and does not move much.", "sitting"},
        {"A person lies down on a bed and gets up again.", "lying"},
        {"A person stands idle.", "standing"},
        {"The person hops on one foot.", "jumping"},
        {"A person strolls through the park.", "walking"},
        {"A person waves both hands.", ""},
    };
    for (const auto& [sentence, activity] : cases) EXPECT_EQ(activity_named_in(sentence), activity) << sentence;
}

TEST(ActivityNames, EveryShippedPromptNamesItsLabelledActivity) {
    // The prompt sets' labels and words must agree, or retrieval would look for the wrong motion. UMAFall's
    // gestures (applauding, bending, hands_up) have no canonical class and are left out.
    int checked = 0;
    for (const char* set : {"realworld", "sisfall", "umafall"}) {
        std::ifstream in(test::source_dir() + "/prompts/" + set + ".tsv");
        ASSERT_TRUE(in) << set;
        std::string line;
        while (std::getline(in, line)) {
            if (line.empty() || line[0] == '#') continue;
            const size_t tab = line.find('\t');
            const std::string label = canonical_activity(line.substr(0, tab)), text = line.substr(tab + 1);
            if (label == "applauding" || label == "bending" || label == "hands_up") continue;
            const std::string named = activity_named_in(text);
            EXPECT_TRUE(shows_activity(named, label) || named == label) << set << ": " << text << " -> " << named;
            ++checked;
        }
    }
    EXPECT_EQ(checked, 80 + 50 + 70);
}

TEST(ActivityNames, StairsShownByEitherDirection) {
    EXPECT_TRUE(shows_activity("stairs_up", "stairs"));
    EXPECT_TRUE(shows_activity("stairs_down", "stairs"));
    EXPECT_FALSE(shows_activity("stairs", "stairs_up"));
    EXPECT_FALSE(shows_activity("walking", "running"));
}

}  // namespace
}  // namespace t2imu
