// experiment_config.cpp: read_experiment_config on hand-written TOML files: every key lands in its field, absent
// keys keep the option objects' defaults, and each rule is refused naming the file and the field: required keys,
// unknown keys (top level and every table), negative seeds, names with '/', ' ' or '-', duplicates and "real",
// no [[source]] or [[real]], L_acc sources that do not exist or only one of before/after, an unknown sampler,
// HAR settings out of range; the shipped experiments/paper.toml and coverage.toml, and edits of
// them refused; plan_experiment on a config: every row planned, a bad row refused before any output.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "imu/placement.hpp"
#include "pipeline/experiment.hpp"
#include "pipeline/synth_keys.hpp"
#include "test_util.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {
const char* kMinimal =
    "[[source]]\nname = \"mdm\"\nmodel = \"models/default\"\n"
    "[[real]]\nname = \"sisfall\"\ndataset = \"data/sisfall\"\nprompts = \"prompts/sisfall.tsv\"\nsensors = "
    "\"sisfall\"\n";

const char* kFull =
    "[synth]\nsamples_per_prompt = 3\nbodies = \"preset:male_tall\"\nrealism = \"sisfall\"\n"
    "vocab = \"v.txt\"\nsampler = \"ddim\"\nsteps = 25\nguidance = 2.5\ncaption_anchor = 0.5\nbatch = 8\nseed = "
    "42\nseconds = 4.5\nrate_hz = 64\n"
    "filter = false\ncapture_rate = false\nheight_crossover_hz = 1.5\nstairs_round_trips = true\nmax_retries = "
    "4\nactivity_reference = "
    "\"ref.csv\"\nmin_activity_agreement = "
    "0.6\ndrop_activity_failures = true\n"
    "[[source]]\nname = \"mdm\"\nmodel = \"models/default\"\n"
    "[[source]]\nname = \"mdm_lacc\"\nmodel = \"models/default-lacc\"\n"
    "[[real]]\nname = \"umafall\"\ndataset = \"d/u\"\nprompts = \"p/u.tsv\"\nsensors = \"umafall\"\npositions = "
    "[\"waist\", \"wrist\"]\n"
    "ceiling_folds = -1\nrealism = \"umafall\"\n"
    "[har]\nrepeats = 3\nseed = 9\nmax_epochs = 12\npatience = 2\nbatch = 32\nlearning_rate = 0.002\nrate_hz = "
    "25\nwindow_s = 3\n"
    "overlap = 0.25\ngyro = true\n"
    "[features]\ntsne_points = 500\nperplexity = 20\nseed = 5\n"
    "[lacc]\nbefore = \"mdm\"\nafter = \"mdm_lacc\"\ndataset = \"data/h\"\nsplit = \"val\"\nvocab = \"g.txt\"\nseed = "
    "11\ntau = 0.5\n";

std::string write_config(const std::string& name, const std::string& text) {
    const std::string path = test::scratch_dir("experiment_config_" + name) + "/c.toml";
    write_file_atomic(path, text);
    return path;
}

// The message read_experiment_config throws for `text` ("no error" when it accepts it).
std::string refusal(const std::string& name, const std::string& text) {
    const std::string path = write_config(name, text);
    try {
        read_experiment_config(path);
    } catch (const Error& e) {
        const std::string m = e.what();
        return m.find(path) == std::string::npos ? "message without the path: " + m : m;
    }
    return "no error";
}
}  // namespace

TEST(ExperimentConfig, EveryKeyLandsInItsField) {
    const ExperimentConfig c = read_experiment_config(write_config("full", kFull));
    EXPECT_EQ(c.synth.samples_per_prompt, 3);
    EXPECT_EQ(c.synth.bodies, "preset:male_tall");
    EXPECT_EQ(c.synth.realism, "sisfall");
    EXPECT_EQ(c.synth.vocab, "v.txt");
    EXPECT_EQ(c.synth.sampling.sampler, Sampler::ddim);
    EXPECT_EQ(c.synth.sampling.steps, 25);
    EXPECT_DOUBLE_EQ(c.synth.sampling.guidance, 2.5);
    EXPECT_EQ(c.synth.sampling.caption_anchor, 0.5);
    EXPECT_EQ(c.synth.sampling.batch, 8);
    EXPECT_EQ(c.synth.sampling.seed, 42u);
    EXPECT_DOUBLE_EQ(c.synth.seconds, 4.5);
    EXPECT_DOUBLE_EQ(c.synth.rate_hz, 64);
    EXPECT_FALSE(c.synth.filter);
    EXPECT_FALSE(c.synth.capture_rate);
    EXPECT_DOUBLE_EQ(c.synth.sampling.height_crossover_hz, 1.5);
    EXPECT_TRUE(c.synth.sampling.stairs_round_trips);
    EXPECT_EQ(c.synth.max_retries, 4);
    EXPECT_EQ(c.synth.activity_reference, "ref.csv");
    EXPECT_DOUBLE_EQ(c.synth.min_activity_agreement, 0.6);
    EXPECT_TRUE(c.synth.drop_activity_failures);
    ASSERT_EQ(c.sources.size(), 2u);
    EXPECT_EQ(c.sources[1].name, "mdm_lacc");
    EXPECT_EQ(c.sources[1].model, "models/default-lacc");
    ASSERT_EQ(c.real_sets.size(), 1u);
    const ExperimentRealSet& r = c.real_sets[0];
    EXPECT_EQ(r.name, "umafall");
    EXPECT_EQ(r.dataset, "d/u");
    EXPECT_EQ(r.prompts, "p/u.tsv");
    EXPECT_EQ(r.sensors, "umafall");
    EXPECT_EQ(r.positions, (std::vector<std::string>{"waist", "wrist"}));
    EXPECT_EQ(r.ceiling_folds, -1);
    EXPECT_EQ(r.realism, "umafall");
    EXPECT_EQ(c.har.repeats, 3);
    EXPECT_EQ(c.har.seed, 9u);
    EXPECT_EQ(c.har.max_epochs, 12);
    EXPECT_EQ(c.har.patience, 2);
    EXPECT_EQ(c.har.batch, 32);
    EXPECT_DOUBLE_EQ(c.har.learning_rate, 0.002);
    EXPECT_DOUBLE_EQ(c.windows.rate_hz, 25);
    EXPECT_DOUBLE_EQ(c.windows.window_s, 3);
    EXPECT_DOUBLE_EQ(c.windows.overlap, 0.25);
    EXPECT_TRUE(c.windows.gyro);
    EXPECT_EQ(c.tsne_points, 500);
    EXPECT_DOUBLE_EQ(c.tsne.perplexity, 20);
    EXPECT_EQ(c.feature_seed, 5u);
    EXPECT_EQ(c.lacc.before, "mdm");
    EXPECT_EQ(c.lacc.after, "mdm_lacc");
    EXPECT_EQ(c.lacc.dataset, "data/h");
    EXPECT_EQ(c.lacc.split, "val");
    EXPECT_EQ(c.lacc.vocab, "g.txt");
    EXPECT_EQ(c.lacc.seed, 11u);
    EXPECT_DOUBLE_EQ(c.lacc.tau, 0.5);
}

// [synth] and synth's flags are one list (pipeline/synth_keys.hpp): the test above sets every key of it.
TEST(ExperimentConfig, TheFullConfigSetsEverySharedSynthKey) {
    SynthOptions o;
    std::vector<std::string> keys;
    visit_synth_keys(o, [&](auto k) { keys.push_back(k.key); });
    EXPECT_GE(keys.size(), 18u);
    for (const std::string& key : keys) EXPECT_TRUE(test::contains(kFull, "\n" + key + " = ")) << key;
}

TEST(ExperimentConfig, AbsentKeysKeepTheDefaults) {
    const ExperimentConfig c = read_experiment_config(write_config("minimal", kMinimal));
    const ExperimentConfig defaults;
    const SynthOptions synth;
    EXPECT_EQ(c.synth.sampling.sampler, synth.sampling.sampler);
    EXPECT_EQ(c.synth.sampling.steps, synth.sampling.steps);
    EXPECT_EQ(c.synth.realism, "none");
    EXPECT_FALSE(c.synth.sampling.caption_anchor.has_value());  // each model folder's own weight
    EXPECT_EQ(c.har.repeats, HarOptions().repeats);
    EXPECT_DOUBLE_EQ(c.windows.rate_hz, WindowOptions().rate_hz);
    EXPECT_EQ(c.tsne_points, defaults.tsne_points);
    EXPECT_DOUBLE_EQ(c.lacc.tau, 0.45);  // the paper's threshold
    EXPECT_TRUE(c.lacc.before.empty());  // no L_acc step
    EXPECT_TRUE(c.real_sets[0].positions.empty());
    EXPECT_EQ(c.real_sets[0].ceiling_folds, 0);
    EXPECT_TRUE(c.real_sets[0].realism.empty());
}

TEST(ExperimentConfig, RefusesEachRuleNamingTheField) {
    const std::string base = kMinimal;
    const std::pair<std::string, std::string> cases[] = {
        // {toml, a part of the message}
        {base + "[[source]]\nname = \"x\"\n", "source[1].model"},  // required key
        {base + "[extra]\nx = 1\n", "extra"},                      // unknown table
        {base + "[synth]\nstepz = 3\n", "synth.stepz"},            // unknown keys
        {base + "[features]\nseed = 1\npoints = 3\n", "features.points"},
        {base + "[lacc]\nbefore = \"mdm\"\nafter = \"mdm\"\nsplitt = \"a\"\n", "lacc.splitt"},
        {"[[source]]\nname = \"mdm\"\nmodel = \"m\"\nweight = 1\n" + base.substr(base.find("[[real]]")),
         "source[0].weight"},
        {base + "[synth]\nseed = -1\n", "synth.seed"},  // negative seeds
        {base + "[har]\nseed = -3\n", "har.seed"},
        {base + "[features]\nseed = -1\n", "features.seed"},
        {base + "[lacc]\nseed = -2\n", "lacc.seed"},
        {base + "[synth]\nsampler = \"euler\"\n", "synth.sampler"},  // closed choices
        {base + "[synth]\nsteps = 2.5\n", "synth.steps"},
        {base + "[synth]\ncaption_anchor = \"half\"\n", "synth.caption_anchor"},  // types
        {base + "[har]\nrepeats = 0\n", "har"},                                   // validated ranges
        {base + "[har]\noverlap = 1.5\n", "har"},
        {base + "[[source]]\nname = \"mdm\"\nmodel = \"other\"\n", "source.name"},  // duplicate
        {"[[source]]\nname = \"my model\"\nmodel = \"m\"\n" + base.substr(base.find("[[real]]")), "source.name"},
        {"[[source]]\nname = \"a-b\"\nmodel = \"m\"\n" + base.substr(base.find("[[real]]")), "source.name"},
        {base + "[[real]]\nname = \"real\"\ndataset = \"d\"\nprompts = \"p\"\nsensors = \"s\"\n", "real.name"},
        {base + "[[real]]\nname = \"a/b\"\ndataset = \"d\"\nprompts = \"p\"\nsensors = \"s\"\n", "real.name"},
        {base.substr(0, base.find("[[real]]")), "[[real]]"},                 // none of them
        {base + "[lacc]\nbefore = \"mdm\"\nafter = \"nothing\"\n", "lacc"},  // L_acc sources
        {base + "[lacc]\nbefore = \"mdm\"\n", "lacc"},
    };
    int k = 0;
    for (const auto& [text, field] : cases) {
        const std::string m = refusal("refused_" + std::to_string(k++), text);
        EXPECT_TRUE(test::contains(m, field)) << "expected a refusal naming `" << field << "` for\n"
                                              << text << "\ngot: " << m;
    }
    // A file that is not TOML, and no file at all.
    EXPECT_TRUE(test::contains(refusal("broken", "[[source]\nname ="), "toml"));
    EXPECT_THROW(read_experiment_config(test::scratch_dir("experiment_config_absent") + "/none.toml"), Error);
}

// plan_experiment: every row's synthesis planned at the door, in order, its realism model parsed; a row t2imu synth
// would refuse is refused before anything is written, naming the file, the row and the spelling.
TEST(ExperimentConfig, PlanMakesEveryRowsSynthesisAndRefusesABadRowBeforeAnyOutput) {
    const std::string dir = test::scratch_dir("experiment_plan");
    const std::string prompts = std::string(T2IMU_SOURCE_DIR) + "/prompts/sisfall.tsv";
    const auto config = [&](const std::string& synth_realism, const std::string& second_realism) {
        return "[synth]\nrealism = \"" + synth_realism + "\"\n[[source]]\nname = \"a\"\nmodel = \"models/x\"\n" +
               "[[source]]\nname = \"b\"\nmodel = \"retrieval:d\"\n" +
               "[[real]]\nname = \"one\"\ndataset = \"d1\"\nprompts = \"" + prompts + "\"\nsensors = \"sisfall\"\n" +
               "[[real]]\nname = \"two\"\ndataset = \"d2\"\nprompts = \"" + prompts + "\"\nsensors = \"umafall\"\n" +
               "realism = \"" + second_realism + "\"\n";
    };
    const ExperimentPlan plan =
        plan_experiment(read_experiment_config(write_config("plan", config("none", "sisfall"))), dir + "/out");
    ASSERT_EQ(plan.rows.size(), 4u);
    const std::vector<std::string> names = {"a-one", "b-one", "a-two", "b-two"};
    for (size_t i = 0; i < names.size(); ++i) {
        const ExperimentRowPlan& r = plan.rows[i];
        EXPECT_EQ(experiment_row_name(plan.config.sources[r.source], plan.config.real_sets[r.set]), names[i]);
        EXPECT_EQ(r.synth.options.out, dir + "/out/synth/" + names[i]);
        EXPECT_EQ(r.synth.imu.realism().name, i < 2 ? "none" : "sisfall");
        EXPECT_EQ(r.synth.prompts.size(), plan.rows[0].synth.prompts.size());
    }
    EXPECT_TRUE(std::holds_alternative<RetrievalSpec>(plan.rows[1].synth.source));
    EXPECT_EQ(plan.rows[3].synth.sensors.size(), parse_sensor_sets("umafall").size());
    for (const auto& [synth_realism, second_realism] :
         std::vector<std::pair<std::string, std::string>>{{"sisfal", "sisfall"}, {"none", "sisfal"}}) {
        const std::string path = write_config("plan_bad", config(synth_realism, second_realism));
        const std::string m =
            test::error_message([&] { plan_experiment(read_experiment_config(path), dir + "/refused"); });
        EXPECT_TRUE(test::contains(m, path) && test::contains(m, "sisfal")) << m;
        EXPECT_TRUE(test::contains(m, synth_realism == "sisfal" ? "real set one" : "real set two")) << m;
        EXPECT_FALSE(fs::exists(dir + "/refused"));
    }
    // A value out of range is checked where synth's flags are: by plan_synth.
    const std::string anchor =
        write_config("plan_anchor", "[synth]\ncaption_anchor = 1.5\n" + config("none", "none").substr(8));
    const std::string m =
        test::error_message([&] { plan_experiment(read_experiment_config(anchor), dir + "/refused"); });
    EXPECT_TRUE(test::contains(m, anchor) && test::contains(m, "caption-anchor") && test::contains(m, "1.5")) << m;
    EXPECT_FALSE(fs::exists(dir + "/refused"));
}

// The shipped configurations (this test was in test_experiment.cpp).
TEST(ExperimentConfig, ShippedConfigsReadAndEditsAreRefused) {
    const ExperimentConfig c = read_experiment_config(std::string(T2IMU_SOURCE_DIR) + "/experiments/paper.toml");
    ASSERT_EQ(c.sources.size(), 3u);
    EXPECT_EQ(c.sources[1].model, "models/default-lacc");
    ASSERT_EQ(c.real_sets.size(), 2u);
    EXPECT_EQ(c.real_sets[0].positions, (std::vector<std::string>{"waist"}));
    EXPECT_EQ(c.real_sets[0].ceiling_folds, 4);
    EXPECT_EQ(c.har.repeats, 10);
    EXPECT_DOUBLE_EQ(c.windows.rate_hz, 20);
    EXPECT_EQ(c.synth.sampling.sampler, Sampler::dpmpp);  // t2imu synth's default, from SynthOptions
    EXPECT_EQ(c.lacc.after, "mdm_lacc");
    EXPECT_EQ(c.synth.realism, "none");  // the paper's pipeline: the ideal sensor
    const ExperimentConfig coverage =
        read_experiment_config(std::string(T2IMU_SOURCE_DIR) + "/experiments/coverage.toml");
    EXPECT_EQ(coverage.real_sets[0].realism, "sisfall");
    // The realism ablation: one [[real]] variant per lever, each spelled from the realism table.
    const ExperimentConfig ablation =
        read_experiment_config(std::string(T2IMU_SOURCE_DIR) + "/experiments/realism-ablation.toml");
    ASSERT_EQ(ablation.real_sets.size(), 11u);
    EXPECT_EQ(ablation.real_sets[1].realism, "sisfall-sensor");
    for (const ExperimentRealSet& set : ablation.real_sets) EXPECT_EQ(set.dataset, "cache/imu/sisfall") << set.name;
    // Every experiment configuration in experiments/ reads (the training configs hold no [[real]]).
    for (const auto& e : fs::directory_iterator(std::string(T2IMU_SOURCE_DIR) + "/experiments")) {
        if (e.path().extension() != ".toml" || read_file_text(e.path().string()).find("[[real]]") == std::string::npos)
            continue;
        EXPECT_NO_THROW(read_experiment_config(e.path().string())) << e.path();
    }

    const std::string dir = test::scratch_dir("experiment_config");
    const std::string base = read_file_text(std::string(T2IMU_SOURCE_DIR) + "/experiments/paper.toml");
    const auto refused = [&](const std::string& text, const std::string& field) {
        write_file_atomic(dir + "/c.toml", text);
        try {
            read_experiment_config(dir + "/c.toml");
        } catch (const Error& e) {
            return std::string(e.what()).find(field) != std::string::npos;
        }
        return false;
    };
    EXPECT_TRUE(refused(base + "\n[extra]\nx = 1\n", "extra"));
    std::string typo = base;
    typo.replace(typo.find("max_epochs"), 10, "max_epoch");
    EXPECT_TRUE(refused(typo, "har.max_epoch"));
    std::string twice = base;
    twice.replace(twice.find("name = \"retrieval\""), 18, "name = \"mdm\"");
    EXPECT_TRUE(refused(twice, "source.name"));
    std::string unknown = base;
    unknown.replace(unknown.find("after = \"mdm_lacc\""), 18, "after = \"nothing\"");
    EXPECT_TRUE(refused(unknown, "lacc"));
}

// Every shipped experiment plans: its prompt sets, sensors, bodies and realism spellings (presets or files under
// experiments/) are what t2imu synth accepts. Paths in them are relative to the checkout, as the CLI runs them.
TEST(ExperimentConfig, ShippedConfigsPlanEveryRow) {
    const fs::path was = fs::current_path();
    fs::current_path(T2IMU_SOURCE_DIR);
    int configs = 0, planned = 0;
    for (const auto& e : fs::directory_iterator("experiments")) {
        if (e.path().extension() != ".toml" || read_file_text(e.path().string()).find("[[real]]") == std::string::npos)
            continue;
        ++configs;
        try {
            planned += !plan_experiment(read_experiment_config(e.path().string()), test::scratch_dir("shipped_plan"))
                            .rows.empty();
        } catch (const Error& error) {
            ADD_FAILURE() << error.what();
        }
    }
    fs::current_path(was);
    EXPECT_GT(configs, 0);
    EXPECT_EQ(planned, configs);
}
