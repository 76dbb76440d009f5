// The paper's experiment end to end on a tiny model and a tiny "real" set (synthesised with other seeds and
// bodies): every output is made, the merged HAR results are the per-seed trainings, a model compared with itself
// changes L_acc by exactly 0 %, and a rerun with more repeats trains only the new seeds (reading configs:
// test_experiment_config.cpp).
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <filesystem>
#include <fstream>

#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/json_file.hpp"
#include "diffusion/trainer.hpp"
#include "pipeline/experiment.hpp"
#include "test_util.hpp"
#include "tiny_model.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {

struct Fixture {
    std::string dir, data, model, prompts, real;
};

// A tiny model and a "real" set: the same prompts synthesised by that model from other seeds, on three other
// bodies (three subjects for the leave-subjects-out ceiling).
Fixture make_fixture(const std::string& dir) {
    torch::set_num_threads(1);
    Fixture f;
    f.dir = dir;
    f.data = test::make_tiny_motion_dataset(dir + "/data");
    f.model = dir + "/model";
    train_mdm(read_train_config(test::write_tiny_train_config(dir, f.data, f.model)), false, "", 10);
    f.prompts = dir + "/prompts.tsv";
    std::ofstream(f.prompts) << "walking\ta person walks forward slowly\nrunning\tsomeone walks\n";
    SynthOptions real;
    real.prompts = f.prompts;
    real.model = f.model;
    real.samples_per_prompt = 2;
    real.sampling.sampler = Sampler::dpmpp;
    real.sampling.steps = 4;
    real.sampling.seed = 500;
    real.seconds = 4;
    real.bodies = "preset:male_tall+preset:female_average+preset:male_adipose";
    real.sensors = "sisfall";
    real.filter = false;
    real.out = dir + "/real";
    run_synth(plan_synth(real));
    f.real = real.out;
    return f;
}

ExperimentConfig tiny_config(const Fixture& f) {
    ExperimentConfig c;
    c.synth.samples_per_prompt = 2;
    c.synth.sampling.sampler = Sampler::dpmpp;
    c.synth.sampling.steps = 4;
    c.synth.seconds = 4;
    c.synth.bodies = "preset:male_average+preset:female_short";
    c.synth.filter = false;
    c.synth.vocab = f.data + "/vocab.safetensors";
    c.sources = {{"tiny", f.model}, {"same", f.model}, {"retrieval", "retrieval:" + f.data}};
    c.real_sets = {{"fake", f.real, f.prompts, "sisfall", {"waist"}, 2, ""}};
    c.har.repeats = 2;
    c.har.max_epochs = 2;
    c.tsne_points = 20;
    c.lacc = {"tiny", "same", f.data, "train", f.data + "/vocab.safetensors", 0, 0.45};
    return c;
}

fs::file_time_type modified(const std::string& path) { return fs::last_write_time(path); }

}  // namespace

TEST(Experiment, RunsEveryStepAndResumesWithMoreRepeats) {
    const std::string dir = test::scratch_dir("experiment");
    const Fixture f = make_fixture(dir);
    ExperimentConfig c = tiny_config(f);
    const std::string out = dir + "/results";
    const nlohmann::json s = experiment_summary_json(run_experiment(plan_experiment(c, out)));
    EXPECT_EQ(read_json_file(out + "/summary.json"), s);  // the table on disk is the one returned

    ASSERT_EQ(s["rows"].size(), 3u);
    for (const auto& row : s["rows"]) {
        const std::string id = row["source"].get<std::string>() + "-fake";
        EXPECT_TRUE(fs::exists(out + "/synth/" + id + "/manifest.csv")) << id;
        EXPECT_EQ(row["classes"], (nlohmann::json{"running", "walking"}));
        EXPECT_DOUBLE_EQ(row["chance"].get<double>(), 0.5);
        // The merged result holds the two per-seed trainings, in seed order.
        const HarResult merged = read_har_result(out + "/har/" + id + ".json");
        ASSERT_EQ(merged.runs.size(), 2u);
        for (int k = 0; k < 2; ++k) {
            const HarResult one = read_har_result(out + "/runs/" + id + "/seed-" + std::to_string(k) + ".jsonl");
            EXPECT_EQ(merged.runs[static_cast<size_t>(k)].balanced_accuracy, one.runs[0].balanced_accuracy);
            EXPECT_EQ(row["balanced_accuracy"]["runs"][static_cast<size_t>(k)].get<double>(),
                      one.runs[0].balanced_accuracy);
        }
        const nlohmann::json gap = nlohmann::json::parse(read_file_text(out + "/gap/" + id + ".json"));
        EXPECT_EQ(row["two_sample_balanced_accuracy"], gap["classifier_two_sample_test"]["balanced_accuracy"]);
        // Signal statistics of the set's one position, synthetic beside real, for the classes both hold.
        const nlohmann::json stats = nlohmann::json::parse(read_file_text(out + "/signal-stats/" + id + "-waist.json"));
        EXPECT_TRUE(stats.contains("walking")) << id;
        EXPECT_GT(stats["walking"]["mag_sd"]["real"].get<double>(), 0) << id;
        EXPECT_GT(stats["walking"]["mag_sd"]["synthetic"].get<double>(), 0) << id;
    }
    // Two sources are the same model with the same seeds: the same synthetic set, byte for byte.
    EXPECT_EQ(read_file_text(out + "/features/tiny-fake.csv"), read_file_text(out + "/features/same-fake.csv"));
    // L_acc of a model against itself on the same draws: no change in any group.
    ASSERT_TRUE(s.contains("lacc"));
    for (const auto& [group, g] : s["lacc"]["groups"].items())
        EXPECT_EQ(g["change_percent"].get<double>(), 0.0) << group;
    EXPECT_GT(s["lacc"]["groups"]["all"]["samples"].get<double>(), 0);
    // The ceiling: two folds over the three real subjects, on the rows' classes.
    ASSERT_EQ(s["ceilings"].size(), 1u);
    EXPECT_EQ(s["ceilings"][0]["classes"], (nlohmann::json{"running", "walking"}));
    EXPECT_EQ(s["ceilings"][0]["balanced_accuracy"]["runs"].size(), 2u);
    // t-SNE: at most 20 windows of each group (real + three sources), labelled by source.
    const CsvTable tsne = read_csv(out + "/tsne/fake.csv");
    EXPECT_EQ(tsne.header.front(), "source");
    EXPECT_EQ(tsne.header.back(), "tsne_y");
    size_t expected = 0;
    for (const std::string group : {"real", "tiny", "same", "retrieval"})
        expected += std::min<size_t>(20, read_csv(out + "/features/" + group + "-fake.csv").rows.size());
    EXPECT_EQ(tsne.rows.size(), expected);
    EXPECT_GT(expected, 60u);
    EXPECT_NE(read_file_text(out + "/summary.md").find("| tiny (" + f.model + ") |"), std::string::npos);
    EXPECT_TRUE(fs::exists(out + "/report/index.html"));

    // A third repeat trains only seed 2; what was done is not touched.
    const auto seed0 = modified(out + "/runs/tiny-fake/seed-0.jsonl"),
               features = modified(out + "/features/real-fake.csv"), ceiling = modified(out + "/har/ceiling-fake.json");
    c.har.repeats = 3;
    const nlohmann::json again = experiment_summary_json(run_experiment(plan_experiment(c, out)));
    EXPECT_EQ(modified(out + "/runs/tiny-fake/seed-0.jsonl"), seed0);
    EXPECT_EQ(modified(out + "/features/real-fake.csv"), features);
    EXPECT_EQ(modified(out + "/har/ceiling-fake.json"), ceiling);
    EXPECT_TRUE(fs::exists(out + "/runs/retrieval-fake/seed-2.jsonl"));
    EXPECT_EQ(again["rows"][0]["balanced_accuracy"]["runs"].size(), 3u);
    EXPECT_EQ(again["rows"][0]["balanced_accuracy"]["runs"][0], s["rows"][0]["balanced_accuracy"]["runs"][0]);

    // Other synthesis settings into the same folder are refused by the synthetic sets' settings check.
    c.synth.seconds = 3;
    EXPECT_THROW(run_experiment(plan_experiment(c, out)), Error);
}
