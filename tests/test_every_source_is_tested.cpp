// Every library source file (src/ outside cli/) has a test file of its name, tests/test_<name>.cpp, or is listed
// below with the test that covers it and the text in that test that shows it (the header it includes, or the
// command or behaviour it drives). A new source file without either fails here, and so does a stale entry.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "test_util.hpp"

namespace fs = std::filesystem;

namespace {

struct Coverage {
    std::string test, evidence;
};

// Source (below src/, without .cpp) -> the test that covers it. Most are parts of a larger concept tested as a
// whole (the body model, HAR, the report, the text encoders); the rest are driven through the CLI or a pipeline.
const std::map<std::string, Coverage> kCoveredBy = {
    {"analysis/domain_gap", {"test_two_sample.cpp", "#include \"analysis/domain_gap.hpp\""}},
    {"analysis/lacc_analysis", {"test_activity_categories.cpp", "#include \"analysis/lacc_analysis.hpp\""}},
    {"body/body_population", {"test_body.cpp", "#include \"body/body_population.hpp\""}},
    {"body/body_spec", {"test_body.cpp", "#include \"body/body_spec.hpp\""}},
    {"body/procedural_body", {"test_body.cpp", "#include \"body/procedural_body.hpp\""}},
    {"core/zip_archive", {"test_realworld.cpp", "#include \"core/zip_archive.hpp\""}},
    {"data/clip_activities",
     {"test_caption_anchor.cpp", "running;jogging"}},  // clips.csv's tags, folded to canonical names
    {"diffusion/mdm_io", {"test_mdm.cpp", "model forward"}},
    {"diffusion/text_to_motion", {"test_clip.cpp", "#include \"diffusion/text_to_motion.hpp\""}},
    {"har/class_map", {"test_har.cpp", "#include \"har/class_map.hpp\""}},
    {"har/datasets/importers", {"test_dataset_profile.cpp", "#include \"har/datasets/importers.hpp\""}},
    {"har/datasets/hugadb", {"test_imu_loaders.cpp", "#include \"har/datasets/hugadb.hpp\""}},
    {"har/datasets/sisfall", {"test_imu_loaders.cpp", "#include \"har/datasets/sisfall.hpp\""}},
    {"har/datasets/umafall", {"test_imu_loaders.cpp", "#include \"har/datasets/umafall.hpp\""}},
    {"har/har_metrics", {"test_har.cpp", "#include \"har/har_metrics.hpp\""}},
    {"har/nn/deepconvlstm", {"test_har.cpp", "#include \"har/nn/deepconvlstm.hpp\""}},
    {"har/nn/har_training", {"test_har.cpp", "#include \"har/nn/har_training.hpp\""}},
    {"har/windowing", {"test_har.cpp", "#include \"har/windowing.hpp\""}},
    {"imu/realworld_export", {"test_cli_imu_synth.cpp", "--format realworld"}},
    {"motion/jump_series", {"test_jump_rescale.cpp", "#include \"motion/jump_series.hpp\""}},
    {"motion/skeleton", {"test_foot_contacts.cpp", "#include \"motion/skeleton.hpp\""}},
    {"report/html_page", {"test_report.cpp", "#include \"report/html_page.hpp\""}},
    {"report/html_report", {"test_report.cpp", "#include \"report/html_report.hpp\""}},
    {"report/pose_strip", {"test_report.cpp", "#include \"report/pose_strip.hpp\""}},
    {"report/signal_stats", {"test_report.cpp", "#include \"report/signal_stats.hpp\""}},
    {"text/caption_index", {"test_caption_anchor.cpp", "#include \"text/caption_index.hpp\""}},
    {"text/clip_bpe", {"test_clip.cpp", "#include \"text/clip_bpe.hpp\""}},
    {"text/nn/clip_text_encoder", {"test_clip.cpp", "#include \"text/nn/clip_text_encoder.hpp\""}},
    {"text/prompt_set", {"test_prompts.cpp", "#include \"text/prompt_set.hpp\""}},
    {"text/sentence_similarity", {"test_text.cpp", "#include \"text/sentence_similarity.hpp\""}},
    {"text/training_captions", {"test_caption_anchor.cpp", "#include \"text/training_captions.hpp\""}},
    {"text/utf8", {"test_text.cpp", "#include \"text/utf8.hpp\""}},
    {"text/word_tokenizer", {"test_text.cpp", "#include \"text/word_tokenizer.hpp\""}},
    {"text/word_vectors", {"test_motion_source.cpp", "#include \"text/word_vectors.hpp\""}},
    {"text/wordpiece", {"test_text.cpp", "#include \"text/wordpiece.hpp\""}},
};

std::string read_text(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST(EverySourceIsTested, ByATestOfItsNameOrAListedOne) {
    const fs::path root(T2IMU_SOURCE_DIR);
    int sources = 0, listed_used = 0;
    for (const auto& e : fs::recursive_directory_iterator(root / "src")) {
        if (e.path().extension() != ".cpp") continue;
        const std::string relative = fs::relative(e.path(), root / "src").replace_extension().generic_string();
        if (relative.rfind("cli/", 0) == 0) continue;
        ++sources;
        if (fs::exists(root / "tests" / ("test_" + e.path().stem().string() + ".cpp"))) continue;
        const auto it = kCoveredBy.find(relative);
        if (it == kCoveredBy.end()) {
            ADD_FAILURE() << "src/" << relative << ".cpp has no tests/test_" << e.path().stem().string()
                          << ".cpp and no entry here";
            continue;
        }
        ++listed_used;
        const std::string test = read_text(root / "tests" / it->second.test);
        EXPECT_NE(test.find(it->second.evidence), std::string::npos)
            << it->second.test << " does not show \"" << it->second.evidence << "\"";
    }
    EXPECT_EQ(listed_used, static_cast<int>(kCoveredBy.size()))
        << "an entry names a source that has a test of its own or is gone";
    EXPECT_GE(sources, 140);  // 143 library sources on 2026-12-04
}
