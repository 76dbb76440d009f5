// t2imu har run: DeepConvLSTM trained on one IMU dataset, tested on another (or leave-one-subject-out).
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "core/parse.hpp"
#include "har/class_map.hpp"
#include "har/nn/deepconvlstm.hpp"
#include "har/nn/har_training.hpp"

namespace t2imu::cli {

namespace {

struct HarArgs {
    std::string train, test, positions, test_positions, channels = "acc", classes, out;
    int folds = 0;
    bool loso = false;
    WindowOptions windows;
    HarOptions options;
};

void run(HarArgs a) {
    WindowOptions w = a.windows;
    w.gyro = a.channels == "acc,gyr";
    w.positions = split_list(a.positions);
    WindowOptions wt = w;
    if (!a.test_positions.empty()) wt.positions = split_list(a.test_positions), wt.positions_option = "--test-positions";
    a.options.verbose = global_options().verbose;
    check_usage([&] {
        if (a.loso == !a.test.empty()) throw Error("har run", "--test", "either --test DATASET or --loso");
        if (a.channels != "acc" && a.channels != "acc,gyr") throw Error("--channels", "channels", "acc or acc,gyr", a.channels);
        if (wt.positions.size() != w.positions.size())
            throw Error("--test-positions", "positions", std::to_string(w.positions.size()) + " positions, one per training position");
        if (a.folds < 0) throw Error("har run", "--folds", "0 (one per subject) or more", std::to_string(a.folds));
        w.validate();
        if (std::lround(w.window_s * w.rate_hz) < kDeepConvLstmMinWindow)
            throw Error("--window", std::to_string(w.window_s) + " s", "at least " + std::to_string(kDeepConvLstmMinWindow) +
                        " samples at --rate (DeepConvLSTM's four convolutions of kernel 5)");
        a.options.validate();
        check_output(a.out, "--out", OutputKind::file, {a.train, a.test});
    });
    if (!a.classes.empty()) {  // checked on the manifest, before any samples are read
        std::set<std::string> held;
        for (const ImuRecording& r : read_imu_dataset(a.train, false)) held.insert(map_activity(r.dataset, r.activity));
        for (const std::string& c : split_list(a.classes))
            if (!held.count(c)) throw UsageError("--classes: " + c + ": expected a class of the training set");
    }
    WindowSet train = make_windows(read_imu_dataset(a.train), w);
    if (!a.classes.empty()) {
        std::map<std::string, std::string> keep;
        for (const std::string& c : split_list(a.classes)) keep[c] = c;
        train = relabel(train, keep);
    }
    HarResult result;
    std::string description;
    if (a.loso) {
        result = leave_one_subject_out(train, a.options, a.folds);
        description = (a.folds > 0 ? std::to_string(a.folds) + "-fold leave-subjects-out on " : "leave-one-subject-out on ") + a.train;
    } else {
        const WindowSet test = make_windows(read_imu_dataset(a.test), wt);
        result = train_and_test(train, test, a.options);
        description = "trained on " + a.train + ", tested on " + a.test;
    }
    write_file_atomic(a.out, har_result_json(result, description));
    double mean = 0;
    for (const HarRun& r : result.runs) mean += r.balanced_accuracy / static_cast<double>(result.runs.size());
    std::printf("%s: balanced accuracy %.4f over %zu runs, %zu classes, %zu train / %zu test windows\n", a.out.c_str(), mean,
                result.runs.size(), result.classes.size(), result.train_windows, result.test_windows);
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& har = command_group(root, "har", "human activity recognition on IMU datasets");
    auto* cmd = har.add_subcommand("run", "train DeepConvLSTM on --train, test on --test (or --loso); writes RESULT.json");
    static HarArgs a;
    cmd->add_option("--train", a.train, "training dataset (manifest.csv layout)")->required()->check(CLI::ExistingDirectory);
    cmd->add_option("--test", a.test, "test dataset")->check(CLI::ExistingDirectory);
    cmd->add_flag("--loso", a.loso, "leave-one-subject-out on --train instead of a test set");
    cmd->add_option("--positions", a.positions, "training positions, comma-separated (a name without side matches either side)");
    cmd->add_option("--test-positions", a.test_positions, "test positions, in the order of --positions");
    cmd->add_option("--channels", a.channels, "acc or acc,gyr");
    cmd->add_option("--rate", a.windows.rate_hz, "evaluation rate, Hz");
    cmd->add_option("--window", a.windows.window_s, "window length, s");
    cmd->add_option("--overlap", a.windows.overlap, "window overlap, 0..1");
    cmd->add_option("--folds", a.folds, "with --loso: subjects dealt into this many folds (default: one per subject)");
    cmd->add_option("--classes", a.classes, "keep only these training classes (after the data set's class map)");
    cmd->add_option("--repeats", a.options.repeats, "trainings with consecutive seeds");
    cmd->add_option("--epochs", a.options.max_epochs, "most epochs per training (early stopping, patience 5)");
    cmd->add_option("--seed", a.options.seed, "first seed");
    cmd->add_option("--out", a.out, "RESULT.json")->required();
    cmd->callback([] { run(a); });
});

}  // namespace t2imu::cli
