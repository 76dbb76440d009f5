// Motion sources: retrieval answers with clips that show the prompt's activity, by tags and classifier.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "diffusion/trainer.hpp"
#include "motion/humanml3d.hpp"
#include "motion/motion_activity.hpp"
#include "pipeline/motion_source.hpp"
#include "test_util.hpp"
#include "text/word_vectors.hpp"
#include "tiny_model.hpp"

namespace t2imu {
namespace {

// The tiny walk dataset (six clips c0..c5) relabelled: c0-c2 are tagged walking but captioned "a person runs
// fast", c3-c5 tagged running but captioned "a person walks". Captions alone would send a running prompt to
// the walking clips.
std::string misleading_dataset(const std::string& name) {
    const std::string dir = test::make_tiny_motion_dataset(test::scratch_dir(name));
    CsvTable clips;
    clips.header = {"id", "activity_tags", "split"};
    for (int k = 0; k < 6; ++k) {
        const bool walking = k < 3;
        std::ofstream(dir + "/texts/c" + std::to_string(k) + ".txt")
            << (walking ? "a person runs fast" : "a person walks") << "##0.0#0.0\n";
        clips.rows.push_back({"c" + std::to_string(k), walking ? "walking" : "running", "train"});
    }
    write_csv(dir + "/clips.csv", clips);
    const std::vector<std::string> words = {"a", "person", "walks", "runs", "fast", "jogs", "claps"};
    std::vector<float> v(words.size() * 100);
    for (size_t i = 0; i < v.size(); ++i)
        v[i] = static_cast<float>(std::cos(0.37 * static_cast<double>(i)) + (i % 100 == i / 100 ? 3 : 0));
    WordVectors(words, v).save(dir + "/vocab.safetensors");
    return dir;
}

std::set<std::string> clips_drawn(MotionSource& s, const std::string& prompt, const std::string& label,
                                  std::string* tier = nullptr) {
    std::set<std::string> out;
    for (uint64_t seed = 0; seed < 40; ++seed) {
        s.generate({prompt}, {label}, {seed}, 40);
        out.insert(s.draw_record(0)["clip"].get<std::string>());
        if (tier) *tier = s.draw_record(0)["tier"];
    }
    return out;
}

TEST(MotionSource, RetrievalTakesTheAskedActivityFromTheLabelOrTheWordsNotTheCaptions) {
    const std::string data = misleading_dataset("retrieval_tags");
    auto source = open_motion_source(parse_motion_source("retrieval:" + data), SampleOptions{}, "cpu",
                                     data + "/vocab.safetensors");
    const std::set<std::string> running = {"c3", "c4", "c5"}, walking = {"c0", "c1", "c2"};
    std::string tier;
    EXPECT_EQ(clips_drawn(*source, "a person runs fast", "jogging", &tier), running);  // SisFall's label
    EXPECT_EQ(tier, "tags");
    EXPECT_EQ(clips_drawn(*source, "a person jogs", ""), running);  // no label: the words
    EXPECT_EQ(clips_drawn(*source, "a person runs fast", "walking"), walking);
    source->generate({"a person walks"}, {"running"}, {3}, 40);
    EXPECT_TRUE(source->draw_record(0)["tags_show_activity"].get<bool>());
    EXPECT_EQ(source->draw_record(0)["activity_asked"], "running");
    // A gesture no clip is tagged with: every clip competes on its captions (the top 5 of 6, and the sixth, whose
    // caption is one of theirs).
    EXPECT_EQ(clips_drawn(*source, "a person claps", "applauding", &tier).size(), 6u);
    EXPECT_EQ(tier, "any");
}

TEST(MotionSource, RetrievalDrawsFromEveryClipTiedWithTheKth) {
    // Six walking clips with one caption (as derived clips share theirs): the five best by similarity are every
    // one of them, so draws reach all six, not the first five listed.
    const std::string data = misleading_dataset("retrieval_ties");
    CsvTable clips;
    clips.header = {"id", "activity_tags", "split"};
    for (int k = 0; k < 6; ++k) {
        std::ofstream(data + "/texts/c" + std::to_string(k) + ".txt") << "a person walks##0.0#0.0\n";
        clips.rows.push_back({"c" + std::to_string(k), "walking", "train"});
    }
    write_csv(data + "/clips.csv", clips);
    auto source = open_motion_source(parse_motion_source("retrieval:" + data), SampleOptions{}, "cpu",
                                     data + "/vocab.safetensors");
    EXPECT_EQ(clips_drawn(*source, "a person walks", "walking"),
              (std::set<std::string>{"c0", "c1", "c2", "c3", "c4", "c5"}));
}

TEST(MotionSource, RetrievalRanksClipsNamingThePromptsAttributesFirst) {
    // Five walks captioned "a person walks" match "a person walks slowly" best by meaning ("slowly" is not in the
    // vocabulary); over a build with measured captions the one whose caption says "slowly" ranks above them and is
    // drawn, over one without it never is.
    const std::string data = misleading_dataset("retrieval_attributes");
    CsvTable clips;
    clips.header = {"id", "activity_tags", "split"};
    for (int k = 0; k < 6; ++k) {
        std::ofstream(data + "/texts/c" + std::to_string(k) + ".txt")
            << (k == 5 ? "a person jogs slowly" : "a person walks") << "##0.0#0.0\n";
        clips.rows.push_back({"c" + std::to_string(k), "walking", "train"});
    }
    write_csv(data + "/clips.csv", clips);
    auto by_meaning = open_motion_source(parse_motion_source("retrieval:" + data), SampleOptions{}, "cpu",
                                         data + "/vocab.safetensors");
    EXPECT_FALSE(by_meaning->describe()["match_attributes"].get<bool>());
    EXPECT_FALSE(clips_drawn(*by_meaning, "a person walks slowly", "walking").count("c5"));
    std::ofstream(data + "/summary.json") << R"({"clips": 6, "measured_captions": 1})";
    auto source = open_motion_source(parse_motion_source("retrieval:" + data), SampleOptions{}, "cpu",
                                     data + "/vocab.safetensors");
    EXPECT_TRUE(source->describe()["match_attributes"].get<bool>());
    EXPECT_EQ(clips_drawn(*source, "a person walks", "walking"), (std::set<std::string>{"c0", "c1", "c2", "c3", "c4"}));
    EXPECT_TRUE(clips_drawn(*source, "a person walks slowly", "walking").count("c5"));
}

TEST(MotionSource, RetrievalPrefersTaggedClipsTheClassifierAgreesWith) {
    // The reference places every clip's motion (all cut from one captured walk) in walking, running far away:
    // walking prompts get the tags+classifier tier; running ones fall back to the tags alone.
    const std::string data = misleading_dataset("retrieval_classifier");
    std::vector<ActivityExample> reference;
    for (int k = 0; k < 6; ++k) {
        const std::string file = data + "/new_joint_vecs/c" + std::to_string(k) + ".npy";
        const MotionDescriptors d = describe_motion(recover_from_ric(feature_matrix_from_array(read_npy(file), file)));
        MotionDescriptors far = d;
        for (double& x : far) x += 10;
        reference.push_back({"walking", "w" + std::to_string(k), d});
        reference.push_back({"running", "r" + std::to_string(k), far});
    }
    const std::string csv = data + "/reference.csv";
    write_csv(csv, MotionActivityClassifier(reference).reference_table());
    auto source = open_motion_source(parse_motion_source("retrieval:" + data), SampleOptions{}, "cpu",
                                     data + "/vocab.safetensors", csv);
    std::string tier;
    EXPECT_EQ(clips_drawn(*source, "a person runs fast", "walking", &tier), (std::set<std::string>{"c0", "c1", "c2"}));
    EXPECT_EQ(tier, "tags+classifier");
    EXPECT_EQ(clips_drawn(*source, "a person walks", "running", &tier), (std::set<std::string>{"c3", "c4", "c5"}));
    EXPECT_EQ(tier, "tags");
    EXPECT_EQ(source->draw_record(0)["classifier"], "walking");
}

// A dataset's capture-rate copies (dataset_builder.hpp): the retrieval draw's copy shows the same instants of the
// same clip as the 20 fps draw, time warp and crop included. The copies here join the clips' frames by curves
// (test::add_capture_copies), so they agree with the 20 fps draw's linear time warp up to the difference of the
// two interpolations between 20 fps frames; a clip without a copy gives none.
TEST(MotionSource, RetrievalGivesTheSameSpanAtTheCaptureRate) {
    const std::string data = misleading_dataset("retrieval_capture_rate");
    test::add_capture_copies(data, {"c0", "c1", "c2", "c3", "c4"});
    auto source = open_motion_source(parse_motion_source("retrieval:" + data), SampleOptions{}, "cpu",
                                     data + "/vocab.safetensors");
    int with_copy = 0, without = 0;
    for (uint64_t seed = 0; seed < 30; ++seed) {
        const JointSequence draw =
            source->generate({"a person walks"}, {seed % 2 ? "walking" : "running"}, {seed}, 30)[0];
        const std::optional<JointSequence> copy = source->capture_rate_motion(0);
        if (source->draw_record(0)["clip"] == "c5") {
            EXPECT_FALSE(copy.has_value());
            ++without;
            continue;
        }
        ++with_copy;
        ASSERT_TRUE(copy.has_value());
        EXPECT_DOUBLE_EQ(copy->fps, 60);
        EXPECT_EQ(copy->num_frames, 3 * (draw.num_frames - 1) + 1);
        double error = 0, step = 0;  // mean over joints and frames: copy against draw, and one 20 fps frame's travel
        for (int k = 0; k + 1 < draw.num_frames; ++k)
            for (int j = 0; j < 22; ++j) {
                error += (copy->at(3 * k, j) - draw.at(k, j)).norm();
                step += (draw.at(k + 1, j) - draw.at(k, j)).norm();
            }
        EXPECT_LT(error, 0.05 * step) << "seed " << seed;
    }
    EXPECT_GT(with_copy, 0);
    EXPECT_GT(without, 0);

    // A dataset whose copies do not hold together is refused when the source opens, naming the field or file.
    auto refused_naming = [&](const std::string& what) {
        try {
            open_motion_source(parse_motion_source("retrieval:" + data), SampleOptions{}, "cpu",
                               data + "/vocab.safetensors");
            ADD_FAILURE() << "accepted; expected an error naming " << what;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    CsvTable clips = read_csv(data + "/clips.csv");
    const CsvTable good = clips;
    clips.rows[0][clips.column("capture_start_s")] = "0.5";
    write_csv(data + "/clips.csv", clips);
    refused_naming("capture_start_s");
    write_csv(data + "/clips.csv", good);
    std::filesystem::remove(data + "/capture_joints/c1.npy");
    refused_naming("c1.npy");
}

// A tiny model folder trained 10 steps on `data` (in a scratch folder `name`): its motions are noise-like, its
// sampling path the real one.
std::string barely_trained_model(const std::string& name, const std::string& data) {
    const std::string model = test::scratch_dir(name) + "/model";
    train_mdm(read_train_config(test::write_tiny_train_config(test::scratch_dir(name), data, model)), false, "", 10);
    return model;
}

// DPM-Solver++ in 4 steps: enough to run the sampling path.
SampleOptions four_step_sampling() {
    SampleOptions sampling;
    sampling.sampler = Sampler::dpmpp;
    sampling.steps = 4;
    return sampling;
}

// The largest coordinate difference between two motions of the same size, m.
double largest_difference(const JointSequence& x, const JointSequence& y) {
    double most = 0;
    for (size_t k = 0; k < x.positions.size(); ++k)
        most = std::max(most, (x.positions[k] - y.positions[k]).cwiseAbs().maxCoeff());
    return most;
}

// The hybrid: retrieval's clip for the prompt (tags as above), noised to the strength and finished by a (tiny,
// barely trained) model: motions of the asked length, seeded, recorded as hybrid with retrieval's draw record.
TEST(MotionSource, HybridFinishesTheRetrievedClipWithTheModel) {
    torch::set_num_threads(1);
    const std::string data = misleading_dataset("hybrid");
    const std::string model = barely_trained_model("hybrid_model", data);
    const SampleOptions sampling = four_step_sampling();
    auto source = open_motion_source(parse_motion_source("hybrid:" + model + "," + data + ",0.3"), sampling, "cpu",
                                     data + "/vocab.safetensors");
    const std::vector<JointSequence> a =
        source->generate({"a person jogs", "a person walks"}, {"running", "walking"}, {5, 6}, 40);
    ASSERT_EQ(a.size(), 2u);
    EXPECT_EQ(a[0].num_frames, 40);
    EXPECT_TRUE(std::set<std::string>({"c3", "c4", "c5"}).count(source->draw_record(0)["clip"].get<std::string>()));
    EXPECT_TRUE(std::set<std::string>({"c0", "c1", "c2"}).count(source->draw_record(1)["clip"].get<std::string>()));
    const nlohmann::json d = source->describe();
    EXPECT_EQ(d["kind"], "hybrid");
    EXPECT_DOUBLE_EQ(d["strength"].get<double>(), 0.3);
    EXPECT_EQ(d["retrieval"]["kind"], "retrieval");
    EXPECT_EQ(d["sampler"], "dpmpp");
    const std::vector<JointSequence> b = source->generate({"a person jogs"}, {"running"}, {5}, 40);
    EXPECT_LT(largest_difference(a[0], b[0]), 1e-4);  // the same seed, the same motion (up to float rounding)
}

// Stairs both ways with stairs_round_trips: the prompt is drawn as an ascent and a descent joined at a stance, at the
// asked length; a (tiny, barely trained) model's halves may have no stance to join at, and then the prompt is drawn
// as without the option, from the same seed. Other prompts are untouched.
TEST(MotionSource, AStairsRoundTripJoinsItsHalvesOrIsDrawnWhole) {
    torch::set_num_threads(1);
    const std::string data = misleading_dataset("round_trip");
    const std::string model = barely_trained_model("round_trip_model", data);
    SampleOptions sampling = four_step_sampling();
    const std::vector<std::string> prompts = {"a person walks up the stairs and back down", "a person walks"};
    const std::vector<std::string> activities = {"", "walking"};
    auto plain = open_motion_source(parse_motion_source(model), sampling, "cpu");
    const std::vector<JointSequence> before = plain->generate(prompts, activities, {5, 6}, 40);
    EXPECT_TRUE(plain->draw_record(0).is_null());
    EXPECT_FALSE(plain->describe().contains("stairs_round_trips"));
    sampling.stairs_round_trips = true;
    auto trips = open_motion_source(parse_motion_source(model), sampling, "cpu");
    const std::vector<JointSequence> after = trips->generate(prompts, activities, {5, 6}, 40);
    EXPECT_EQ(trips->describe()["stairs_round_trips"], true);
    ASSERT_EQ(after.size(), 2u);
    EXPECT_TRUE(trips->draw_record(1).is_null());
    EXPECT_LT(largest_difference(after[1], before[1]), 1e-4);  // up to the batch's float rounding
    const nlohmann::json trip = trips->draw_record(0)["round_trip"];
    ASSERT_TRUE(trip.is_object());
    EXPECT_EQ(after[0].num_frames, 40);
    if (trip["joined"].get<bool>()) {
        EXPECT_GT(trip["splice_frame"].get<int>(), 0);
        EXPECT_LT(trip["splice_frame"].get<int>(), 40);
        EXPECT_GT(largest_difference(after[0], before[0]), 1e-3);
    } else {
        EXPECT_NE(trip["why"].get<std::string>().find("splice"), std::string::npos) << trip["why"];
        EXPECT_LT(largest_difference(after[0], before[0]), 1e-4);
    }
}

}  // namespace
}  // namespace t2imu
