// HAR evaluation: metrics with hand-computed answers, windowing and class maps, resampling, DeepConvLSTM's
// shape, and training that must separate classes a child could tell apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "har/class_map.hpp"
#include "har/har_metrics.hpp"
#include "har/nn/deepconvlstm.hpp"
#include "har/nn/har_training.hpp"
#include "har/subject_draw.hpp"
#include "har/windowing.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

// A recording whose acc_x is a sine of `hz` (amplitude 3 m/s^2) over gravity on y, plus noise.
ImuRecording sine_recording(const std::string& subject, const std::string& activity, const std::string& position,
                            double hz, double seconds, double rate, std::mt19937_64& rng,
                            const std::string& trial = "1") {
    ImuRecording r;
    r.dataset = "test";
    r.subject = subject;
    r.activity = activity;
    r.position = position;
    r.rate_hz = rate;
    r.path = "test/" + subject + "/" + activity + "_" + trial + "_" + position + ".csv";
    std::normal_distribution<double> noise(0, 0.3);
    std::uniform_real_distribution<double> phase(0, 2 * M_PI);
    const double p = phase(rng);
    for (int k = 0; k < static_cast<int>(seconds * rate); ++k) {
        const double t = k / rate;
        r.t.push_back(t);
        r.samples.push_back({3 * std::sin(2 * M_PI * hz * t + p) + noise(rng), 9.81 + noise(rng), noise(rng), 0, 0, 0});
    }
    return r;
}

}  // namespace

TEST(HarMetrics, HandComputedConfusion) {
    // truth: 0 0 0 0 1 1 2 2 ; predicted: 0 0 1 0 1 0 2 1
    const Confusion c = confusion_matrix({0, 0, 0, 0, 1, 1, 2, 2}, {0, 0, 1, 0, 1, 0, 2, 1}, 4);
    EXPECT_EQ(c[0], (std::vector<long>{3, 1, 0, 0}));
    const std::vector<double> recall = per_class_recall(c);
    EXPECT_DOUBLE_EQ(recall[0], 0.75);
    EXPECT_DOUBLE_EQ(recall[1], 0.5);
    EXPECT_TRUE(std::isnan(recall[3]));  // class 3 absent: left out of the averages
    EXPECT_DOUBLE_EQ(balanced_accuracy(c), (0.75 + 0.5 + 0.5) / 3);
    // F1: class 0 = 2*3/(4+4) = 0.75; class 1 = 2*1/(2+3) = 0.4; class 2 = 2*1/(2+1) = 2/3.
    EXPECT_DOUBLE_EQ(macro_f1(c), (0.75 + 0.4 + 2.0 / 3.0) / 3);
    EXPECT_THROW(confusion_matrix({0, 5}, {0, 1}, 4), Error);
}

TEST(HarClassMap, DocumentedMapsAndStairsCoarsening) {
    EXPECT_EQ(map_activity("sisfall", "jogging"), "running");
    EXPECT_EQ(map_activity("sisfall", "stairs_up_down"), "stairs");
    EXPECT_EQ(map_activity("sisfall", "jump_reach"), "");
    EXPECT_EQ(map_activity("umafall", "jumping"), "jumping");
    EXPECT_EQ(map_activity("t2imu", "stairs_up"), "stairs_up");
    EXPECT_EQ(map_activity("t2imu", "jogging"), "running");  // a prompt set in SisFall's or UMAFall's own names
    EXPECT_EQ(map_activity("t2imu", "stairs_up_down"), "stairs");
    EXPECT_EQ(map_activity("t2imu", "jump_reach"), "jump_reach");
    EXPECT_EQ(coarsen_for("stairs_up", {"stairs_up", "walking"}, {"stairs", "walking"}), "stairs");
    EXPECT_EQ(coarsen_for("stairs_up", {"stairs_up"}, {"stairs_up"}), "stairs_up");
}

TEST(HarWindowing, CountsPositionsAndRates) {
    std::mt19937_64 rng(1);
    std::vector<ImuRecording> recs = {sine_recording("s1", "walking", "left_shin", 1, 10, 50, rng),
                                      sine_recording("s1", "walking", "waist", 1, 10, 50, rng),
                                      sine_recording("s1", "jogging", "waist", 2, 6, 50, rng)};
    recs[2].dataset = "sisfall";  // jogging -> running
    WindowOptions o;
    o.positions = {"waist"};
    WindowSet w = make_windows(recs, o);
    // 10 s at 50 Hz -> 500 samples -> 200 at 20 Hz: windows of 40 every 20: (200 - 40) / 20 + 1 = 9; 6 s -> 5.
    EXPECT_EQ(w.size(), 14u);
    EXPECT_EQ(w.length, 40);
    EXPECT_EQ(w.channels, 3);
    EXPECT_EQ(std::count(w.labels.begin(), w.labels.end(), "running"), 5);
    o.positions = {"shin", "waist"};  // "shin" matches left_shin; only the walking trial has both
    o.gyro = true;
    w = make_windows(recs, o);
    EXPECT_EQ(w.size(), 9u);
    EXPECT_EQ(w.channels, 12);
    o.positions.clear();
    EXPECT_THROW(make_windows(recs, o), Error);  // two positions: the caller must choose
}

TEST(HarWindowing, ResamplingKeepsASlowSineIntact) {
    for (double rate_in : {50.0, 58.82, 200.0}) {
        std::vector<double> x;
        for (int k = 0; k < static_cast<int>(10 * rate_in); ++k) x.push_back(std::sin(2 * M_PI * 1.0 * k / rate_in));
        const std::vector<double> y = resample_channel(x, rate_in, 20);
        double worst = 0;
        for (size_t k = 20; k + 20 < y.size(); ++k)
            worst = std::max(worst, std::fabs(y[k] - std::sin(2 * M_PI * k / 20.0)));
        EXPECT_LT(worst, 0.02) << rate_in;  // a 1 Hz sine is far below the 10 Hz Nyquist frequency of 20 Hz
    }
}

TEST(DeepConvLstm, ShapesAndParameterCountAsPublished) {
    DeepConvLstm model(6, 4);
    const torch::Tensor y = model->forward(torch::randn({5, 40, 6}));
    EXPECT_EQ(y.sizes(), (std::vector<int64_t>{5, 4}));
    int64_t n = 0;
    for (const torch::Tensor& p : model->parameters()) n += p.numel();
    const int64_t conv = (1 * 64 * 5 + 64) + 3 * (64 * 64 * 5 + 64);
    const int64_t lstm =
        4 * 128 * (64 * 6 + 128) + 8 * 128 + 4 * 128 * (128 + 128) + 8 * 128;  // two bias vectors per layer
    EXPECT_EQ(n, conv + lstm + 128 * 4 + 4);
}

TEST(HarTraining, SeparatesSinesOfDifferentFrequencyAcrossDataSets) {
    torch::set_num_threads(1);
    std::mt19937_64 rng(7);
    std::vector<ImuRecording> train, test;
    const std::vector<std::pair<std::string, double>> classes = {
        {"walking", 0.8}, {"running", 2.5}, {"stairs_up", 5.0}};
    for (const auto& [name, hz] : classes)
        for (int s = 0; s < 4; ++s)
            train.push_back(sine_recording("s" + std::to_string(s), name, "waist", hz, 12, 50, rng));
    for (const auto& [name, hz] : classes)
        test.push_back(sine_recording("t", name == "stairs_up" ? "stairs" : name, "waist", hz, 12, 50, rng));
    const WindowSet tr = make_windows(train, {}), te = make_windows(test, {});
    HarOptions o;
    o.repeats = 2;
    o.max_epochs = 15;
    const HarResult r = train_and_test(tr, te, o);
    EXPECT_EQ(r.classes, (std::vector<std::string>{"running", "stairs", "walking"}));  // stairs_up coarsened
    ASSERT_EQ(r.runs.size(), 2u);
    for (const HarRun& run : r.runs) EXPECT_GT(run.balanced_accuracy, 0.9);
    const nlohmann::json j = nlohmann::json::parse(har_result_json(r, "sines"));
    EXPECT_EQ(j["balanced_accuracy"]["runs"].size(), 2u);
    EXPECT_TRUE(j["per_class_recall"].contains("stairs"));
    long total = 0;
    for (const auto& row : j["confusion"])
        for (const auto& v : row) total += v.get<long>();
    EXPECT_EQ(total, static_cast<long>(2 * r.test_windows));  // summed over the two runs

    // One training per seed, written, read back and merged, is the two-run result: how the experiment resumes.
    std::vector<HarResult> parts;
    for (uint64_t seed = 0; seed < 2; ++seed) {
        HarOptions one = o;
        one.repeats = 1;
        one.seed = seed;
        const std::string path = test::scratch_dir("har_seed_" + std::to_string(seed)) + "/result.json";
        write_file_atomic(path, har_result_json(train_and_test(tr, te, one), "one seed"));
        parts.push_back(read_har_result(path));
    }
    const HarResult merged = merge_har_results(parts);
    ASSERT_EQ(merged.runs.size(), 2u);
    EXPECT_EQ(merged.run_names, r.run_names);
    for (size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(merged.runs[k].balanced_accuracy, r.runs[k].balanced_accuracy);
        EXPECT_EQ(merged.runs[k].confusion, r.runs[k].confusion);
        EXPECT_EQ(merged.runs[k].epochs, r.runs[k].epochs);
    }
    EXPECT_EQ(nlohmann::json::parse(har_result_json(merged, "sines"))["confusion"], j["confusion"]);
    HarResult other = parts[1];
    other.classes.pop_back();
    EXPECT_THROW(merge_har_results({parts[0], other}), Error);
    // A damaged result is one Error naming the file and the key, not a JSON library exception.
    const std::string damaged = test::scratch_dir("har_damaged") + "/result.json";
    nlohmann::json doc = nlohmann::json::parse(har_result_json(parts[0], "one seed"));
    for (const auto& [key, spoil] :
         std::vector<std::pair<std::string, nlohmann::json>>{{"run_records.0.macro_f1", "high"},
                                                             {"run_records.0.confusion", nlohmann::json::array({1, 2})},
                                                             {"classes", 3}}) {
        nlohmann::json bad = doc;
        const size_t dot = key.find(".0.");
        if (dot == std::string::npos)
            bad[key] = spoil;
        else
            bad["run_records"][0][key.substr(dot + 3)] = spoil;
        write_file_atomic(damaged, bad.dump());
        const std::string e = test::error_message([&] { read_har_result(damaged); });
        EXPECT_TRUE(test::contains(e, damaged + ": " + key)) << key << ": " << e;
    }
}

TEST(HarTraining, CliLeaveOneSubjectOut) {
    std::mt19937_64 rng(9);
    std::vector<ImuRecording> recs;
    for (int s = 0; s < 3; ++s)
        for (const auto& [name, hz] : std::vector<std::pair<std::string, double>>{{"walking", 0.8}, {"jumping", 4.0}})
            recs.push_back(sine_recording("s" + std::to_string(s), name, "chest", hz, 12, 20, rng));
    const std::string dir = test::scratch_dir("har_cli");
    write_imu_dataset(dir + "/data", recs);
    const auto r =
        test::run_cli("--threads 1 har run --train " + dir + "/data --loso --epochs 8 --out " + dir + "/r.json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(read_file_text(dir + "/r.json"));
    EXPECT_EQ(j["classes"], (std::vector<std::string>{"jumping", "walking"}));
    EXPECT_EQ(j["balanced_accuracy"]["runs"].size(), 3u);  // one per subject
    EXPECT_GT(j["balanced_accuracy"]["mean"].get<double>(), 0.85);
    const auto bad =
        test::run_cli("har run --train " + dir + "/data --out " + dir + "/x.json");  // neither --test nor --loso
    EXPECT_EQ(bad.exit_code, 2) << bad.output;                                       // bad usage
}

namespace {

// A synthetic-like set (subjects named as bodies) and a real-like set of `subjects` subjects, three sine classes.
struct TwoSets {
    std::vector<ImuRecording> synthetic, real;
};

TwoSets two_sets(int subjects) {
    std::mt19937_64 rng(11);
    TwoSets s;
    const std::vector<std::pair<std::string, double>> classes = {{"walking", 0.8}, {"running", 2.5}, {"lying", 5.0}};
    for (const auto& [name, hz] : classes)
        for (const char* body : {"male_average", "female_tall"})
            for (int trial = 0; trial < 2; ++trial) {
                s.synthetic.push_back(
                    sine_recording(body, name, "waist", hz * 1.1, 10, 50, rng, std::to_string(trial)));
                s.synthetic.back().dataset = "t2imu";
            }
    for (int subject = 0; subject < subjects; ++subject)
        for (const auto& [name, hz] : classes)
            for (int trial = 0; trial < 2; ++trial)
                s.real.push_back(sine_recording("SA0" + std::to_string(subject), name, "waist", hz, 10, 50, rng,
                                                std::to_string(trial)));
    return s;
}

}  // namespace

TEST(HarTraining, FinetuneWithZeroEpochsIsPlainTrainingOnTheSyntheticSet) {
    torch::set_num_threads(1);
    const TwoSets s = two_sets(4);
    const WindowSet syn = make_windows(s.synthetic, {}), real = make_windows(s.real, {});
    HarOptions o;
    o.repeats = 1;
    o.max_epochs = 4;
    o.seed = 5;
    SeveralSetsOptions m;
    m.protocol = HarProtocol::finetune;
    m.test_set = 1;
    m.train_subjects = 2;
    m.finetune_epochs = 0;
    const HarResult tuned = train_on_sets({{&syn, "syn"}, {&real, "real"}}, real, o, m);
    ASSERT_EQ(tuned.runs.size(), 1u);
    const std::vector<std::string> drawn = tuned.runs[0].train_subjects;
    EXPECT_EQ(drawn, draw_subjects(real.subjects, 2, 5, 0));  // the draw is the recorded one
    std::vector<ImuRecording> rest;
    for (const ImuRecording& r : s.real)
        if (std::find(drawn.begin(), drawn.end(), r.dataset + ":" + r.subject) == drawn.end())
            rest.push_back(r);  // windows name dataset:subject
    const HarResult plain = train_and_test(syn, make_windows(rest, {}), o);
    EXPECT_EQ(tuned.classes, plain.classes);
    EXPECT_EQ(tuned.runs[0].confusion, plain.runs[0].confusion);  // bitwise: the same network predicts the same windows
    EXPECT_EQ(tuned.runs[0].balanced_accuracy, plain.runs[0].balanced_accuracy);
    EXPECT_EQ(tuned.runs[0].epochs, plain.runs[0].epochs);
    EXPECT_EQ(tuned.runs[0].test_subjects.size(), 2u);
    EXPECT_EQ(tuned.runs[0].set_windows,
              (std::vector<size_t>{syn.size(), real.size() / 2}));  // each subject the same windows
    // Fine-tuning on the drawn subjects moves the network off the pretrained one.
    m.finetune_epochs = 3;
    const HarResult more = train_on_sets({{&syn, "syn"}, {&real, "real"}}, real, o, m);
    EXPECT_GT(more.runs[0].epochs, 0);
    EXPECT_EQ(more.runs[0].train_subjects, drawn);
    // With shares the fine-tuning goes on with the synthetic set beside the drawn subjects: the same draw, the shares
    // recorded, and a checkpoint of fine-tuning on the drawn subjects alone is not resumed as one of it.
    m.shares = {0.5, 0.5};
    HarCheckpoint alone{more, nullptr};
    EXPECT_TRUE(test::contains(test::error_message([&] {
                                   train_on_sets({{&syn, "syn"}, {&real, "real"}}, real, o, m, nullptr, &alone);
                               }),
                               "checkpoint"));
    const HarResult both = train_on_sets({{&syn, "syn"}, {&real, "real"}}, real, o, m);
    EXPECT_EQ(both.shares, m.shares);
    EXPECT_EQ(both.runs[0].train_subjects, drawn);
    EXPECT_GT(both.runs[0].epochs, 0);
}

// A series stopped after its first run and resumed from what it saved (read back from disk) is the uninterrupted
// series: the same draws, epochs and predictions, the windows summed over all runs; a checkpoint of other draws is
// refused.
TEST(HarTraining, ACheckpointedSeriesResumesToTheUninterruptedOne) {
    torch::set_num_threads(1);
    const TwoSets s = two_sets(4);
    const WindowSet syn = make_windows(s.synthetic, {}), real = make_windows(s.real, {});
    HarOptions o;
    o.repeats = 3;
    o.max_epochs = 3;
    SeveralSetsOptions m;
    m.protocol = HarProtocol::finetune;
    m.test_set = 1;
    m.train_subjects = 1;
    m.finetune_epochs = 2;
    std::vector<HarResult> saved;
    HarCheckpoint record{{}, [&](const HarResult& r) { saved.push_back(r); }};
    const HarResult whole = train_on_sets({{&syn, "syn"}, {&real, "real"}}, real, o, m, nullptr, &record);
    ASSERT_EQ(saved.size(), 3u);
    EXPECT_EQ(saved[0].runs.size(), 1u);
    const std::string file = test::scratch_dir("har_checkpoint") + "/first.json";
    write_file_atomic(file, har_result_json(saved[0], "the first run"));
    HarCheckpoint resume{read_har_result(file), [&](const HarResult& r) { saved.push_back(r); }};
    const HarResult resumed = train_on_sets({{&syn, "syn"}, {&real, "real"}}, real, o, m, nullptr, &resume);
    EXPECT_EQ(saved.size(), 5u);  // two more runs saved
    ASSERT_EQ(resumed.runs.size(), 3u);
    for (size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(resumed.runs[k].train_subjects, whole.runs[k].train_subjects) << k;
        EXPECT_EQ(resumed.runs[k].epochs, whole.runs[k].epochs) << k;
        EXPECT_EQ(resumed.runs[k].confusion, whole.runs[k].confusion) << k;
    }
    EXPECT_EQ(resumed.run_names, whole.run_names);
    EXPECT_EQ(resumed.train_windows, whole.train_windows);
    EXPECT_EQ(resumed.test_windows, whole.test_windows);
    m.train_subjects = 2;  // other draws
    EXPECT_TRUE(test::contains(test::error_message([&] {
                                   train_on_sets({{&syn, "syn"}, {&real, "real"}}, real, o, m, nullptr, &resume);
                               }),
                               "checkpoint"));
}

TEST(HarTraining, MixDrawsSubjectsPerRepeatAndTestsTheOthers) {
    torch::set_num_threads(1);
    const TwoSets s = two_sets(4);
    const WindowSet syn = make_windows(s.synthetic, {}), real = make_windows(s.real, {});
    HarOptions o;
    o.repeats = 2;
    o.max_epochs = 30;
    o.batch = 16;  // an epoch at these shares: 2 x the drawn subject's windows, 4 batches
    SeveralSetsOptions m;
    m.test_set = 1;
    m.train_subjects = 1;
    m.shares = {0.5, 0.5};
    const HarResult r = train_on_sets({{&syn, "syn"}, {&real, "real"}}, real, o, m);
    EXPECT_EQ(r.protocol, "mix");
    EXPECT_EQ(r.classes, (std::vector<std::string>{"lying", "running", "walking"}));
    ASSERT_EQ(r.runs.size(), 2u);
    for (int k = 0; k < 2; ++k) {
        const HarRun& run = r.runs[static_cast<size_t>(k)];
        EXPECT_EQ(run.train_subjects, draw_subjects(real.subjects, 1, 0, k));
        EXPECT_EQ(run.test_subjects.size(), 3u);
        EXPECT_EQ(std::count(run.test_subjects.begin(), run.test_subjects.end(), run.train_subjects[0]), 0);
        EXPECT_EQ(run.set_windows, (std::vector<size_t>{syn.size(), real.size() / 4}));
        EXPECT_GT(run.balanced_accuracy, 0.6);  // separable sines, well above chance (1/3)
    }
    EXPECT_EQ(r.test_windows, 2 * (real.size() * 3 / 4));  // summed over the two draws
    // A subject in a training set and in the test set is refused, before any training.
    m.test_set = -1, m.train_subjects = 0;
    EXPECT_TRUE(test::contains(test::error_message([&] {
                                   train_on_sets({{&syn, "syn"}, {&real, "real"}}, real, o, m);
                               }),
                               "is in both"));
}

TEST(HarTraining, CliTrainsOnSeveralSetsAndRefusesBadSplits) {
    const TwoSets s = two_sets(3);
    const std::string dir = test::scratch_dir("har_cli_sets");
    write_imu_dataset(dir + "/syn", s.synthetic);
    write_imu_dataset(dir + "/real", s.real);
    const std::string base =
        "--threads 1 har run --train " + dir + "/syn --train " + dir + "/real --test " + dir + "/real --epochs 3 ";
    const auto r = test::run_cli(
        base + "--train-subjects 1 --protocol finetune --finetune-epochs 2 --repeats 2 --out " + dir + "/r.json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const HarResult result = read_har_result(dir + "/r.json");
    EXPECT_EQ(result.training_sets, (std::vector<std::string>{dir + "/syn", dir + "/real"}));
    EXPECT_EQ(result.protocol, "finetune");
    ASSERT_EQ(result.runs.size(), 2u);
    EXPECT_EQ(result.runs[0].train_subjects.size(), 1u);
    EXPECT_EQ(result.runs[1].test_subjects.size(), 2u);
    // Refused in one line, exit 2, before any training (no result written).
    std::vector<ImuRecording> unnamed = s.real;
    for (ImuRecording& rec : unnamed) rec.subject = "";
    write_imu_dataset(dir + "/unnamed", unnamed);
    for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
             {"--train " + dir + "/real --test " + dir + "/real", "SA00 is in both"},
             {base + "--train-subjects 3", "--train-subjects: 3: expected from 0 to 2"},
             {"--train " + dir + "/syn --train " + dir + "/unnamed --test " + dir + "/unnamed --train-subjects 1",
              "recordings name their subject"},
             {base + "--train-subjects 1 --train-share 0.9", "2 shares, one per --train"},
             {base + "--protocol finetune", "--train-subjects to fine-tune on"}}) {
        const std::string command =
            (args.rfind("--threads", 0) == 0 ? args : "--threads 1 har run " + args) + " --out " + dir + "/bad.json";
        const auto bad = test::run_cli(command);
        EXPECT_EQ(bad.exit_code, 2) << command << "\n" << bad.output;
        EXPECT_TRUE(test::contains(bad.output, message)) << command << "\n" << bad.output;
        EXPECT_FALSE(std::filesystem::exists(dir + "/bad.json"));
    }
}
