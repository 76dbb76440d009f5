// har/har_result: RESULT.json written and read back (the report and the experiment read it typed), merged, and
// refused with one Error naming the file and the key when damaged.
#include "har/har_result.hpp"

#include <gtest/gtest.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

HarRun run_of(double ba, const Confusion& c, std::vector<std::string> train = {}, std::vector<std::string> test = {},
              std::vector<size_t> windows = {}) {
    HarRun r;
    r.balanced_accuracy = ba;
    r.macro_f1 = ba - 0.01;
    r.epochs = 7;
    r.seconds_per_epoch = 1.5;
    r.confusion = c;
    r.train_subjects = std::move(train);
    r.test_subjects = std::move(test);
    r.set_windows = std::move(windows);
    return r;
}

// Two draws of a finetune training on a synthetic and a real set.
HarResult drawn_result() {
    HarResult r;
    r.classes = {"running", "walking"};
    r.training_sets = {"out/syn", "cache/imu/sisfall"};
    r.protocol = "finetune";
    r.finetune_epochs = 20;
    r.finetune_learning_rate = 3e-4;
    r.runs = {run_of(0.75, {{3, 1}, {1, 3}}, {"SA02"}, {"SA01", "SA03"}, {400, 60}),
              run_of(0.5, {{2, 2}, {2, 2}}, {"SA03"}, {"SA01", "SA02"}, {400, 70})};
    r.run_names = {"draw 0, seed 0", "draw 1, seed 1"};
    r.train_windows = 930;
    r.test_windows = 16;
    return r;
}

void expect_same(const HarResult& a, const HarResult& b) {
    EXPECT_EQ(a.classes, b.classes);
    EXPECT_EQ(a.run_names, b.run_names);
    EXPECT_EQ(a.training_sets, b.training_sets);
    EXPECT_EQ(a.shares, b.shares);
    EXPECT_EQ(a.protocol, b.protocol);
    EXPECT_EQ(a.finetune_epochs, b.finetune_epochs);
    EXPECT_EQ(a.finetune_learning_rate, b.finetune_learning_rate);
    EXPECT_EQ(a.train_windows, b.train_windows);
    EXPECT_EQ(a.test_windows, b.test_windows);
    ASSERT_EQ(a.runs.size(), b.runs.size());
    for (size_t k = 0; k < a.runs.size(); ++k) {
        EXPECT_EQ(a.runs[k].balanced_accuracy, b.runs[k].balanced_accuracy);
        EXPECT_EQ(a.runs[k].macro_f1, b.runs[k].macro_f1);
        EXPECT_EQ(a.runs[k].epochs, b.runs[k].epochs);
        EXPECT_EQ(a.runs[k].confusion, b.runs[k].confusion);
        EXPECT_EQ(a.runs[k].train_subjects, b.runs[k].train_subjects);
        EXPECT_EQ(a.runs[k].test_subjects, b.runs[k].test_subjects);
        EXPECT_EQ(a.runs[k].set_windows, b.runs[k].set_windows);
    }
}

}  // namespace

TEST(HarResult, RoundTripKeepsDrawsAndWindowsPerSet) {
    const HarResult r = drawn_result();
    const std::string path = test::scratch_dir("har_result_round_trip") + "/r.json";
    write_file_atomic(path, har_result_json(r, "two draws"));
    expect_same(read_har_result(path), r);
    const nlohmann::json j = nlohmann::json::parse(har_result_json(r, "two draws"));
    EXPECT_EQ(j["balanced_accuracy"]["mean"].get<double>(), 0.625);
    EXPECT_NEAR(j["balanced_accuracy"]["sd"].get<double>(), 0.1767767, 1e-6);  // sd (n - 1) of 0.75 and 0.5
    EXPECT_EQ(j["confusion"], nlohmann::json::parse("[[5,3],[3,5]]"));         // summed over the draws
    EXPECT_EQ(j["run_records"][1]["train_windows_per_set"]["cache/imu/sisfall"], 70);
    EXPECT_EQ(j["finetune"]["learning_rate"].get<double>(), 3e-4);
    EXPECT_TRUE(is_har_result(j));
    EXPECT_FALSE(is_har_result(nlohmann::json::parse(R"({"classifier_two_sample_test":{}})")));
}

TEST(HarResult, OneSetResultsKeepTheirLayout) {
    HarResult r;
    r.classes = {"a", "b"};
    r.runs = {run_of(0.9, {{9, 1}, {1, 9}})};
    r.run_names = {"seed 0"};
    const nlohmann::json j = nlohmann::json::parse(har_result_json(r, "one set"));
    EXPECT_FALSE(j.contains("training_sets"));
    EXPECT_FALSE(j["run_records"][0].contains("train_subjects"));
    expect_same(parse_har_result(j, "r.json"), r);
}

TEST(HarResult, MergeSumsDrawsAndRefusesOtherSets) {
    const HarResult r = drawn_result();
    HarResult first = r, second = r;
    first.runs.pop_back(), first.run_names.pop_back();
    second.runs.erase(second.runs.begin()), second.run_names.erase(second.run_names.begin());
    first.train_windows = 460, second.train_windows = 470, first.test_windows = second.test_windows = 8;
    const HarResult merged = merge_har_results({first, second});
    EXPECT_EQ(merged.train_windows, 930u);  // each draw its own split: summed
    EXPECT_EQ(merged.test_windows, 16u);
    EXPECT_EQ(merged.run_names, r.run_names);
    HarResult other = second;
    other.training_sets = {"out/syn"};
    EXPECT_THROW(merge_har_results({first, other}), Error);
    HarResult seeds = first;  // runs without draws must agree on the windows
    seeds.runs[0].train_subjects.clear();
    HarResult seeds2 = seeds;
    seeds2.train_windows += 1;
    EXPECT_THROW(merge_har_results({seeds, seeds2}), Error);
    EXPECT_EQ(merge_har_results({seeds, seeds}).train_windows, seeds.train_windows);
}

TEST(HarResult, DamagedFilesNameTheKey) {
    const std::string path = test::scratch_dir("har_result_damaged") + "/r.json";
    const nlohmann::json good = nlohmann::json::parse(har_result_json(drawn_result(), "x"));
    const auto message = [&](const std::function<void(nlohmann::json&)>& spoil) {
        nlohmann::json bad = good;
        spoil(bad);
        write_file_atomic(path, bad.dump());
        return test::error_message([&] { read_har_result(path); });
    };
    EXPECT_TRUE(test::contains(message([](nlohmann::json& j) { j["run_records"][0]["macro_f1"] = "high"; }),
                               path + ": run_records.0.macro_f1"));
    EXPECT_TRUE(test::contains(message([](nlohmann::json& j) {
                                   j["run_records"][0]["confusion"] = {1, 2};
                               }),
                               path + ": run_records.0.confusion"));
    EXPECT_TRUE(test::contains(message([](nlohmann::json& j) { j["run_records"][1]["train_subjects"] = {3}; }),
                               path + ": run_records.1.train_subjects"));
    EXPECT_TRUE(test::contains(message([](nlohmann::json& j) { j["protocol"] = "blend"; }),
                               path + ": protocol: expected mix or finetune"));
    EXPECT_TRUE(test::contains(
        message([](nlohmann::json& j) { j["run_records"][0]["train_windows_per_set"].erase("out/syn"); }),
        path + ": run_records.0.train_windows_per_set.out/syn"));
    EXPECT_TRUE(test::contains(message([](nlohmann::json& j) { j["classes"] = 3; }), path + ": classes"));
}
