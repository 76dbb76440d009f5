// The data set profiles (imu/dataset_profile): every built-in profile has each part and every table draws from it,
// and a profile made up here runs through import -> reframe -> HAR with no other file changed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "core/csv.hpp"
#include "har/class_map.hpp"
#include "har/datasets/importers.hpp"
#include "har/nn/har_training.hpp"
#include "har/windowing.hpp"
#include "imu/dataset_profile.hpp"
#include "imu/realism.hpp"
#include "imu/reframe.hpp"
#include "test_util.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

TEST(DatasetProfile, EveryProfileHasEachPartAndEveryTableDrawsFromIt) {
    ASSERT_EQ(dataset_profile_names().rfind("realworld, sisfall, umafall, hugadb", 0), 0u);
    for (const DatasetProfile& p : dataset_profiles()) {
        EXPECT_NO_THROW(check_dataset_profile(p)) << p.name;
        EXPECT_TRUE(has_importer(p)) << p.name;
        EXPECT_EQ(builtin_placement_set(p.name).sensors.size(), p.placements.size())
            << p.name;                                              // --sensors, data reframe
        const SensorNoiseModel sensor = parse_noise_model(p.name);  // the realism model's sensor key
        EXPECT_EQ(sensor.name, p.name);
        EXPECT_EQ(sensor.acc_range, p.sensor.acc_range) << p.name;
        EXPECT_EQ(sensor.acc_noise_density, p.sensor.acc_noise_density) << p.name;
        const RealismModel preset = realism_preset(p.name);  // --realism
        EXPECT_EQ(preset.sensor, p.name);
        EXPECT_EQ(preset.tilt.mean_deg, p.tilt_mean_deg) << p.name;
        EXPECT_EQ(preset.tilt.sd_deg, p.tilt_spread_deg) << p.name;
        for (const auto& [label, mapped] : p.class_map)
            EXPECT_EQ(map_activity(p.name, label), mapped) << p.name;  // HAR's classes
        EXPECT_TRUE(test::contains(realism_help(), p.name)) << p.name;
    }
    // The values the tables held before they drew from the profiles.
    EXPECT_EQ(parse_noise_model("sisfall").bits, 13);
    EXPECT_NEAR(parse_noise_model("hugadb").acc_range, 2 * 9.80665, 1e-12);
    EXPECT_EQ(realism_preset("sisfall").tilt.mean_deg, 7.5);
    EXPECT_EQ(realism_preset("smartphone").tilt.sd_deg, realism_preset("realworld").tilt.sd_deg);
    EXPECT_EQ(map_activity("sisfall", "jump_reach"), "");
    EXPECT_EQ(map_activity("umafall", "jogging"), "running");
    EXPECT_EQ(map_activity("t2imu", "stairs_up_down"), "stairs");
    // A profile missing a part, or taking a taken name, is refused by name.
    DatasetProfile bare;
    bare.name = "bare";
    EXPECT_EQ(test::error_message([&] { add_dataset_profile(bare); }),
              "dataset profile bare: about: expected a line saying what was recorded with what");
    DatasetProfile twice = dataset_profiles()[1];
    twice.importer = [](const std::string&, std::vector<std::string>*) { return std::vector<ImuRecording>{}; };
    EXPECT_EQ(test::error_message([&] { add_dataset_profile(twice); }),
              "dataset profile sisfall: name: expected a name no other profile has (got sisfall)");
}

namespace {

// The made-up release format: one CSV per trial, <subject>_<activity>.csv, columns t,ax,ay,az,gx,gy,gz at 50 Hz.
std::vector<ImuRecording> import_toy(const std::string& folder, std::vector<std::string>*) {
    std::vector<ImuRecording> out;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(folder)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
        const CsvTable t = read_csv(f.string());
        ImuRecording r;
        const std::string stem = f.stem().string();
        r.dataset = "toyset", r.subject = stem.substr(0, stem.find('_')), r.activity = stem.substr(stem.find('_') + 1),
        r.position = "waist";
        r.path = "recordings/" + stem + ".csv", r.rate_hz = 50;
        for (size_t i = 0; i < t.rows.size(); ++i) {
            r.t.push_back(t.number(i, 0));
            r.samples.push_back(
                {t.number(i, 1), t.number(i, 2), t.number(i, 3), t.number(i, 4), t.number(i, 5), t.number(i, 6)});
        }
        r.n_samples = r.samples.size();
        out.push_back(std::move(r));
    }
    return out;
}

// A trial: gravity along the sensor's x (its up axis), a sway on y (right) at `hz` and a forward bob on z.
void write_trial(const std::string& file, double hz, double amplitude) {
    std::ofstream out(file);
    out << "t,ax,ay,az,gx,gy,gz\n";
    for (int i = 0; i < 50 * 12; ++i) {
        const double t = i / 50.0, w = 2 * M_PI * hz * t;
        out << t << "," << 9.81 + amplitude * std::sin(2 * w) << "," << amplitude * std::sin(w) << ","
            << 0.5 * amplitude * std::cos(w) << ",0," << 0.3 * std::sin(w) << ",0\n";
    }
}

}  // namespace

TEST(DatasetProfile, AMadeUpProfileRunsImportReframeAndHar) {
    DatasetProfile toy;
    toy.name = "toyset";
    toy.about = "a made-up data set: one board at the waist, x up, z out of the skin";
    SensorPlacement waist = builtin_placement_set("sisfall").sensors[0];
    waist.axis[0] = "up", waist.axis[1] = "", waist.axis[2] = "out";
    toy.placements = {waist};
    toy.sensor = smartphone_sensor();
    toy.sensor.name = "toyset";
    toy.tilt_spread_deg = 3;
    toy.class_map = {{"strolling", "walking"}, {"dashing", "running"}};
    toy.importer = import_toy;
    add_dataset_profile(toy);
    struct Removed {
        ~Removed() { remove_dataset_profile("toyset"); }  // the other tests see the built-in profiles alone
    } removed;
    EXPECT_EQ(realism_preset("toyset").tilt.sd_deg, 3);  // the preset and the device model exist with it
    EXPECT_EQ(parse_noise_model("toyset").name, "toyset");

    const std::string dir = test::scratch_dir("dataset_profile_toy");
    fs::create_directories(dir + "/release");
    for (const char* subject : {"s1", "s2", "s3"}) {
        write_trial(dir + "/release/" + subject + "_strolling.csv", 1.8, 1.0);
        write_trial(dir + "/release/" + subject + "_dashing.csv", 2.8, 6.0);
    }
    // import: the profile's own reader
    std::vector<std::string> skipped;
    write_imu_dataset(dir + "/imported",
                      import_imu_dataset(*find_dataset_profile("toyset"), dir + "/release", &skipped));
    // reframe into SisFall's axes from the convention the dataset column names: SisFall's x (right) is the toy's y,
    // its y (down) the toy's -x, its z (front) the toy's z (out of the skin at the front of the waist).
    const std::vector<ImuRecording> turned =
        reframe_dataset(dir + "/imported", {}, builtin_placement_set("sisfall"), nullptr);
    ASSERT_EQ(turned.size(), 6u);
    const std::vector<ImuRecording> imported = read_imu_dataset(dir + "/imported");
    for (size_t k : {size_t(0), size_t(100)}) {
        EXPECT_NEAR(turned[0].samples[k][0], imported[0].samples[k][1], 1e-9);
        EXPECT_NEAR(turned[0].samples[k][1], -imported[0].samples[k][0], 1e-9);
        EXPECT_NEAR(turned[0].samples[k][2], imported[0].samples[k][2], 1e-9);
    }
    EXPECT_EQ(turned[0].extra.at("frame"), "sisfall");
    // HAR on it: the profile's class map names the classes; leave-one-subject-out tells the two gaits apart.
    WindowOptions w;
    w.rate_hz = 20, w.window_s = 2;
    const WindowSet windows = make_windows(turned, w);
    EXPECT_EQ(std::set<std::string>(windows.labels.begin(), windows.labels.end()),
              (std::set<std::string>{"running", "walking"}));
    HarOptions o;
    o.repeats = 1, o.max_epochs = 15, o.patience = 15, o.batch = 16;
    const HarResult result = leave_one_subject_out(windows, o);
    EXPECT_EQ(result.classes, (std::vector<std::string>{"running", "walking"}));
    ASSERT_EQ(result.runs.size(), 3u);  // one fold per subject
    double mean = 0;
    for (const HarRun& run : result.runs) mean += run.balanced_accuracy / 3;
    EXPECT_GT(mean, 0.8);
}
