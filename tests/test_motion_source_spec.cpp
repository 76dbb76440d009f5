// --model's spelling parsed into the source it names: a model folder, retrieval over a dataset, or the hybrid of the
// two with its strength; malformed hybrids refused in one line naming --model.
#include "pipeline/motion_source_spec.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_util.hpp"

namespace t2imu {
namespace {

TEST(MotionSourceSpec, EachSpellingParsesToItsSource) {
    const MotionSourceSpec model = parse_motion_source("models/default");
    ASSERT_TRUE(std::holds_alternative<ModelFolderSpec>(model));
    EXPECT_EQ(std::get<ModelFolderSpec>(model).folder, "models/default");

    const MotionSourceSpec retrieval = parse_motion_source("retrieval:cache/dataset");
    ASSERT_TRUE(std::holds_alternative<RetrievalSpec>(retrieval));
    EXPECT_EQ(std::get<RetrievalSpec>(retrieval).dataset, "cache/dataset");

    const MotionSourceSpec hybrid = parse_motion_source("hybrid:models/default,cache/dataset,0.3");
    ASSERT_TRUE(std::holds_alternative<HybridSpec>(hybrid));
    EXPECT_EQ(std::get<HybridSpec>(hybrid).model_folder, "models/default");
    EXPECT_EQ(std::get<HybridSpec>(hybrid).dataset, "cache/dataset");
    EXPECT_DOUBLE_EQ(std::get<HybridSpec>(hybrid).strength, 0.3);
    EXPECT_DOUBLE_EQ(std::get<HybridSpec>(parse_motion_source("hybrid:m,d,1")).strength, 1.0);  // the model alone
}

TEST(MotionSourceSpec, MalformedSpellingsAreRefusedNamingModel) {
    for (const std::string bad : {"", "hybrid:m", "hybrid:m,d", "hybrid:m,d,0.5,x", "hybrid:m,d,1.5", "hybrid:m,d,0",
                                  "hybrid:m,d,-0.2", "hybrid:m,d,x", "hybrid:m,d,nan"}) {
        const std::string message = test::error_message([&] { parse_motion_source(bad); });
        EXPECT_TRUE(test::contains(message, "--model")) << bad << ": " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace t2imu
