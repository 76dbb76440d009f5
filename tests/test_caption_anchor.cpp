// The caption anchor: a model's training captions under their clips' activities (captions.tsv), searched by
// meaning within the activity asked, and blended into the prompt's text feature (text_to_motion.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "data/hml3d_dataset.hpp"
#include "diffusion/text_to_motion.hpp"
#include "diffusion/trainer.hpp"
#include "test_util.hpp"
#include "text/caption_index.hpp"
#include "text/training_captions.hpp"
#include "tiny_model.hpp"

namespace t2imu {
namespace {

using test::axis_vocabulary;

TEST(CaptionIndex, SearchesOnlyTheAskedActivityNearestFirst) {
    const WordVectors vocab = axis_vocabulary({{"climbs", {1, 0, 0, 0, 0}},
                                               {"descends", {0.9f, 0.4f, 0, 0, 0}},
                                               {"walks", {0, 0, 1, 0, 0}},
                                               {"strolls", {0, 0, 0.8f, 0.6f, 0}},
                                               {"lies", {0, 0, 0, 0, 1}}});
    const CaptionIndex index(vocab,
                             {{"stairs_down", "descends"},
                              {"stairs_up", "climbs"},
                              {"walking", "strolls"},
                              {"walking", "walks"},
                              {"walking", "walks"},
                              {"lying", "lies"},
                              {"other", "zzz"}},
                             "captions.tsv");
    ASSERT_EQ(index.captions().size(), 6u);  // the repeated (walking, walks) kept once
    // "climbs" is nearer "descends" (cosine 0.91) than any other caption, but a stairs_up prompt searches stairs_up's
    // captions only.
    const auto up = index.nearest("climbs", 5, "stairs_up");
    ASSERT_EQ(up.size(), 1u);
    EXPECT_EQ(index.captions()[up[0].index].text, "climbs");
    EXPECT_NEAR(up[0].similarity, 1.0, 1e-9);
    // "stairs" takes either direction, the nearest caption's, and never both: "descends" gives stairs_down's
    // captions only although "climbs" (stairs_up) is near it, and "climbs" gives stairs_up's.
    const auto down = index.nearest("descends", 5, "stairs");
    ASSERT_EQ(down.size(), 1u);
    EXPECT_EQ(index.captions()[down[0].index].text, "descends");
    const auto climbs = index.nearest("climbs", 5, "stairs");
    ASSERT_EQ(climbs.size(), 1u);
    EXPECT_EQ(index.captions()[climbs[0].index].text, "climbs");
    // k limits; an unknown or absent activity gives nothing (the prompt keeps its own feature).
    const auto walk = index.nearest("walks", 1, "walking");
    ASSERT_EQ(walk.size(), 1u);
    EXPECT_EQ(index.captions()[walk[0].index].text, "walks");
    EXPECT_TRUE(index.nearest("walks", 5, "").empty());
    EXPECT_TRUE(index.nearest("walks", 5, "jumping").empty());
    // A prompt without a known word is equally far from every caption: the earlier ones first.
    const auto unknown = index.nearest("qqq", 5, "walking");
    ASSERT_EQ(unknown.size(), 2u);
    EXPECT_EQ(index.captions()[unknown[0].index].text, "strolls");
    EXPECT_EQ(unknown[0].similarity, 0.0);
}

// "slowly" and "quickly" are near neighbours in GloVe; a caption naming the prompt's attribute ranks first although
// another caption is nearer by meaning, and among captions naming as many, the nearer first.
TEST(CaptionIndex, CaptionsNamingThePromptsAttributesRankFirst) {
    const WordVectors vocab = axis_vocabulary({{"walks", {1, 0, 0, 0}},
                                               {"forward", {0, 1, 0, 0}},
                                               {"slowly", {0, 0, 1, 0}},
                                               {"quickly", {0, 0, 0.95f, 0.3f}},
                                               {"lies", {0, 0, 0, 1}}});
    const CaptionIndex index(vocab,
                             {{"walking", "walks forward quickly"},
                              {"walking", "walks slowly"},
                              {"walking", "walks forward"},
                              {"lying", "lies"}},
                             "captions.tsv");
    const std::string prompt = "walks forward slowly";
    // By meaning alone (the default) the nearer captions come first.
    const auto by_meaning = index.nearest(prompt, 3, "walking");
    ASSERT_EQ(by_meaning.size(), 3u);
    EXPECT_NE(index.captions()[by_meaning[0].index].text, "walks slowly");
    EXPECT_GE(by_meaning[0].similarity, by_meaning[1].similarity);
    const auto by_words = index.nearest(prompt, 3, "walking", true);
    ASSERT_EQ(by_words.size(), 3u);
    EXPECT_EQ(index.captions()[by_words[0].index].text, "walks slowly");  // names pace_slow
    EXPECT_GT(by_words[1].similarity, by_words[0].similarity);            // the others are nearer by meaning
    EXPECT_EQ(index.captions()[by_words[1].index].text, "walks forward quickly");
    EXPECT_EQ(index.captions()[by_words[2].index].text, "walks forward");
    // Without an attribute word the order is by meaning alone.
    const auto plain = index.nearest("walks forward", 1, "walking", true);
    EXPECT_EQ(index.captions()[plain[0].index].text, "walks forward");
}

TEST(CaptionIndex, RefusesCaptionsWithoutAKnownWordNamingTheFile) {
    const WordVectors vocab = axis_vocabulary({{"walks", {1}}});
    try {
        CaptionIndex(vocab, {{"walking", "zzz"}, {"other", "qqq"}}, "model/captions.tsv");
        ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("model/captions.tsv"), std::string::npos) << e.what();
    }
}

// The tiny walk dataset recaptioned and tagged: c0, c1 walking; c2, c3 running; c4, c5 untagged by clips.csv.
std::string tagged_dataset(const std::string& name) {
    const std::string dir = test::make_tiny_motion_dataset(test::scratch_dir(name));
    const std::vector<std::string> captions = {
        "a person walks forward slowly", "someone walks",  "a person walks forward",
        "someone walks forward",         "a person walks", "slowly"};
    CsvTable clips;
    clips.header = {"id", "activity_tags", "split"};
    for (int k = 0; k < 6; ++k) {
        std::ofstream(dir + "/texts/c" + std::to_string(k) + ".txt")
            << captions[static_cast<size_t>(k)] << "##0.0#0.0\n";
        if (k < 4) clips.rows.push_back({"c" + std::to_string(k), k < 2 ? "walking" : "running;jogging", "train"});
    }
    write_csv(dir + "/clips.csv", clips);
    return dir;
}

TEST(TrainingCaptions, TakeTheClipsTagsElseTheirWordsAndReadBackAsAPromptSet) {
    const std::string data = tagged_dataset("training_captions");
    const Hml3dDataset set(data, "train");
    const std::vector<Prompt> got = training_captions(set, data);
    // jogging is running's other name: listed once; c4 and c5 have no row: their words name walking, or nothing.
    const std::vector<std::pair<std::string, std::string>> expected = {{"walking", "a person walks forward slowly"},
                                                                       {"walking", "someone walks"},
                                                                       {"running", "a person walks forward"},
                                                                       {"running", "someone walks forward"},
                                                                       {"walking", "a person walks"},
                                                                       {"other", "slowly"}};
    ASSERT_EQ(got.size(), expected.size());
    for (size_t i = 0; i < got.size(); ++i) EXPECT_EQ(std::make_pair(got[i].activity, got[i].text), expected[i]) << i;
    const std::string path = test::scratch_dir("training_captions_out") + "/captions.tsv";
    write_training_captions(path, got);
    const std::vector<Prompt> back = read_prompt_set(path, PromptActivity::required);
    ASSERT_EQ(back.size(), got.size());
    for (size_t i = 0; i < got.size(); ++i)
        EXPECT_EQ(back[i].activity + "|" + back[i].text, got[i].activity + "|" + got[i].text);
    // The CLI writes the same file.
    const auto r = test::run_cli("data captions --dataset " + data + " --out " + path + ".cli");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(read_file_text(path + ".cli"), read_file_text(path));
    const auto bad = test::run_cli("data captions --dataset " + data + " --split dev --out " + path + ".bad");
    EXPECT_NE(bad.exit_code, 0);
    EXPECT_NE(bad.output.find("--split"), std::string::npos) << bad.output;
    EXPECT_FALSE(std::filesystem::exists(path + ".bad"));
}

torch::Tensor row_mean(MotionModel& m, const std::vector<std::string>& captions) {
    return m.encode_text(captions).mean(0);
}

// A trained folder carries its captions and the anchor's defaults; the feature is the prompt's, the mean of its
// activity's nearest captions' features, or their blend, exactly as the header's formula.
TEST(CaptionAnchor, BlendsThePromptWithItsActivitysNearestCaptions) {
    torch::set_num_threads(1);
    const std::string data = tagged_dataset("anchor_data");
    const std::string model_dir = test::scratch_dir("anchor_model") + "/model";
    train_mdm(read_train_config(test::write_tiny_train_config(test::scratch_dir("anchor_model"), data, model_dir)),
              false, "", 10);
    const nlohmann::json meta = nlohmann::json::parse(read_file_text(model_dir + "/model.json"));
    EXPECT_EQ(meta["caption_anchor"]["captions"], "captions.tsv");
    EXPECT_EQ(meta["caption_anchor"]["neighbours"], kCaptionAnchorNeighbours);
    EXPECT_EQ(meta["caption_anchor"]["weight"], kCaptionAnchorWeight);
    EXPECT_EQ(read_prompt_set(model_dir + "/captions.tsv", PromptActivity::required).size(), 6u);

    auto m = load_motion_model(model_dir);
    torch::NoGradGuard no_grad;
    const std::vector<std::string> prompts = {"a person jogs", "someone claps"};
    const torch::Tensor own = m->encode_text(prompts);
    EXPECT_TRUE(torch::equal(m->condition(prompts, {"running", "walking"}, 0.0), own));
    const torch::Tensor running = row_mean(*m, {"a person walks forward", "someone walks forward"});
    const torch::Tensor walking = row_mean(*m, {"a person walks forward slowly", "someone walks", "a person walks"});
    const torch::Tensor full = m->condition(prompts, {"running", "walking"}, 1.0);
    EXPECT_TRUE(torch::allclose(full[0], running, 1e-5, 1e-6));
    EXPECT_TRUE(torch::allclose(full[1], walking, 1e-5, 1e-6));
    const torch::Tensor half = m->condition(prompts, {"running", ""}, 0.5);
    EXPECT_TRUE(torch::allclose(half[0], 0.5 * own[0] + 0.5 * running, 1e-5, 1e-6));
    EXPECT_TRUE(torch::equal(half[1], own[1]));  // no activity: the prompt alone
    EXPECT_TRUE(torch::equal(m->condition(prompts, {}, 1.0), own));

    // Sampling: the folder's weight by default, --caption-anchor overrides; out-of-range refused before any work.
    std::ofstream(data + "/prompts.tsv") << "running\ta person jogs\n";
    const auto sample = [&](const std::string& out, const std::string& extra) {
        return test::run_cli("--threads 1 sample --model " + model_dir + " --prompts " + data +
                             "/prompts.tsv --frames 40 --sampler dpmpp --steps 3 --out " + data + "/" + out + " " +
                             extra);
    };
    ASSERT_EQ(sample("default", "").exit_code, 0);
    ASSERT_EQ(sample("one", "--caption-anchor 1").exit_code, 0);
    ASSERT_EQ(sample("zero", "--caption-anchor 0").exit_code, 0);
    EXPECT_EQ(read_file_bytes(data + "/default/0000_features.npy"), read_file_bytes(data + "/one/0000_features.npy"));
    EXPECT_NE(read_file_bytes(data + "/default/0000_features.npy"), read_file_bytes(data + "/zero/0000_features.npy"));
    const auto bad = sample("bad", "--caption-anchor 1.5");
    EXPECT_NE(bad.exit_code, 0);
    EXPECT_NE(bad.output.find("--caption-anchor"), std::string::npos) << bad.output;
    EXPECT_FALSE(std::filesystem::exists(data + "/bad"));
}

TEST(CaptionAnchor, ModelJsonFieldsAreCheckedAndAFolderWithoutOneRefusesAWeight) {
    torch::set_num_threads(1);
    const std::string data = tagged_dataset("anchor_fields_data");
    const std::string model_dir = test::scratch_dir("anchor_fields") + "/model";
    train_mdm(read_train_config(test::write_tiny_train_config(test::scratch_dir("anchor_fields"), data, model_dir)),
              false, "", 10);
    const std::string good = read_file_text(model_dir + "/model.json");
    const auto expect_refused = [&](const std::function<void(nlohmann::json&)>& edit, const std::string& field) {
        nlohmann::json j = nlohmann::json::parse(good);
        edit(j);
        write_file_atomic(model_dir + "/model.json", j.dump());
        try {
            load_motion_model(model_dir);
            ADD_FAILURE() << field << " accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
        }
    };
    expect_refused([](nlohmann::json& j) { j["caption_anchor"]["weight"] = 1.5; }, "caption_anchor.weight");
    expect_refused([](nlohmann::json& j) { j["caption_anchor"]["neighbours"] = 0; }, "caption_anchor.neighbours");
    expect_refused([](nlohmann::json& j) { j["caption_anchor"]["match_attributes"] = "yes"; },
                   "caption_anchor.match_attributes");
    expect_refused([](nlohmann::json& j) { j["caption_anchor"].erase("captions"); }, "caption_anchor.captions");
    expect_refused([](nlohmann::json& j) { j["caption_anchor"]["captions"] = "missing.tsv"; }, "missing.tsv");
    // The file is read only inside the model folder, and its errors name the field that led to it.
    expect_refused([](nlohmann::json& j) { j["caption_anchor"]["captions"] = "missing.tsv"; },
                   "model.json: caption_anchor.captions: ");
    std::ofstream(model_dir + "/../outside.tsv") << "walking\ta person walks\n";
    expect_refused([](nlohmann::json& j) { j["caption_anchor"]["captions"] = "../outside.tsv"; },
                   "caption_anchor.captions: ../outside.tsv: expected a relative path inside");
    expect_refused([](nlohmann::json& j) { j["caption_anchor"]["captions"] = "/etc/hostname"; },
                   "caption_anchor.captions: /etc/hostname");
    nlohmann::json none = nlohmann::json::parse(good);
    none.erase("caption_anchor");
    write_file_atomic(model_dir + "/model.json", none.dump());
    auto m = load_motion_model(model_dir);
    torch::NoGradGuard no_grad;
    EXPECT_TRUE(torch::equal(m->condition({"a person jogs"}, {"running"}, 0.0), m->encode_text({"a person jogs"})));
    try {
        m->condition({"a person jogs"}, {"running"}, 1.0);
        ADD_FAILURE() << "a weight without an anchor was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--caption-anchor"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace t2imu
