// t2imu har run: DeepConvLSTM trained on one IMU dataset or several (synthetic plus a few drawn real subjects),
// tested on another (or leave-one-subject-out).
#include <cmath>
#include <cstdio>
#include <filesystem>
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
#include "har/subject_draw.hpp"

namespace t2imu::cli {

namespace {

struct HarArgs {
    std::vector<std::string> train;
    std::string test, positions, test_positions, channels = "acc", classes, out, train_share, protocol;
    int folds = 0, train_subjects = -1;
    SeveralSetsOptions sets;
    bool loso = false;
    WindowOptions windows;
    HarOptions options;
};

// Training on several sets, a draw of subjects, shares or a protocol: train_on_sets rather than train_and_test.
bool several(const HarArgs& a) {
    return a.train.size() > 1 || a.train_subjects >= 0 || !a.train_share.empty() || !a.protocol.empty();
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
    return out;
}

bool same_folder(const std::string& x, const std::string& y) {
    std::error_code ec;
    return std::filesystem::equivalent(x, y, ec);
}

// The several-set options from the flags: the protocol, the shares, and which --train is also the --test set.
void bind_sets(HarArgs& a) {
    if (!a.protocol.empty()) a.sets.protocol = parse_har_protocol(a.protocol, "--protocol");
    for (const std::string& share : split_list(a.train_share))
        a.sets.shares.push_back(finite_number(share, "--train-share", share, "a share of a batch"));
    if (a.train_subjects >= 0) {
        for (size_t i = 0; i < a.train.size(); ++i)
            if (same_folder(a.train[i], a.test)) {
                if (a.sets.test_set >= 0) throw Error("--train", a.train[i], "the --test set named once");
                a.sets.test_set = static_cast<int>(i);
            }
        if (a.sets.test_set < 0)
            throw Error("--train-subjects", std::to_string(a.train_subjects), "a --train that is also the --test set");
        a.sets.train_subjects = a.train_subjects;
    }
    a.sets.validate(a.train.size(), a.options.batch);
}

// The subject split checked on the manifests (subject_draw.hpp's rules), before any samples are read.
void check_manifest_subjects(const HarArgs& a) {
    const auto subjects_of = [](const std::string& set) {
        std::vector<std::string> s;
        for (const ImuRecording& r : read_imu_dataset(set, false)) s.push_back(r.subject);
        return s;
    };
    std::vector<std::vector<std::string>> train;
    for (const std::string& set : a.train) train.push_back(subjects_of(set));
    check_subject_split(train, a.train, subjects_of(a.test), a.sets.test_set, a.sets.train_subjects);
}

// The training classes kept (each mapped to itself; empty: all), checked on the training manifests.
std::map<std::string, std::string> kept_classes(const HarArgs& a) {
    std::map<std::string, std::string> keep;
    if (a.classes.empty()) return keep;
    std::set<std::string> held;
    for (const std::string& set : a.train)
        for (const ImuRecording& r : read_imu_dataset(set, false)) held.insert(map_activity(r.dataset, r.activity));
    for (const std::string& c : split_list(a.classes)) {
        if (!held.count(c)) throw Error("--classes", c, "a class of the training set");
        keep[c] = c;
    }
    return keep;
}

enum class HarMode { loso, one_set, several_sets };

// What `har run` does, every option parsed and checked at the door (manifests read, no samples).
struct HarRunPlan {
    HarMode mode = HarMode::one_set;
    std::vector<std::string> train;  // dataset folders
    std::string test, out;
    int folds = 0;                              // loso: 0 = one fold per subject
    WindowOptions train_windows, test_windows;  // positions and channels included
    std::map<std::string, std::string> keep;    // classes kept (empty: all)
    SeveralSetsOptions sets;                    // several_sets only
    HarOptions options;
};

HarRunPlan plan_har_run(HarArgs a) {
    HarRunPlan p;
    check_usage([&] {
        if (a.loso == !a.test.empty()) throw Error("har run", "--test", "either --test DATASET or --loso");
        if (a.loso && (a.train.size() > 1 || several(a)))
            throw Error("--loso", "several", "one --train and no --train-subjects, --train-share or --protocol");
        bind_sets(a);
        if (a.channels != "acc" && a.channels != "acc,gyr")
            throw Error("--channels", "channels", "acc or acc,gyr", a.channels);
        p.train_windows = a.windows;
        p.train_windows.gyro = a.channels == "acc,gyr";
        p.train_windows.positions = split_list(a.positions);
        p.test_windows = p.train_windows;
        if (!a.test_positions.empty())
            p.test_windows.positions = split_list(a.test_positions),
            p.test_windows.positions_option = "--test-positions";
        if (p.test_windows.positions.size() != p.train_windows.positions.size())
            throw Error("--test-positions", "positions",
                        std::to_string(p.train_windows.positions.size()) + " positions, one per training position");
        if (a.folds < 0) throw Error("har run", "--folds", "0 (one per subject) or more", std::to_string(a.folds));
        p.train_windows.validate();
        if (std::lround(p.train_windows.window_s * p.train_windows.rate_hz) < kDeepConvLstmMinWindow)
            throw Error("--window", std::to_string(p.train_windows.window_s) + " s",
                        "at least " + std::to_string(kDeepConvLstmMinWindow) +
                            " samples at --rate (DeepConvLSTM's four convolutions of kernel 5)");
        a.options.verbose = global_options().verbose;
        a.options.validate();
        a.sets.validate_values();
        std::vector<std::string> inputs = a.train;
        inputs.push_back(a.test);
        check_output(a.out, "--out", OutputKind::file, inputs);
        p.keep = kept_classes(a);
        if (!a.loso) check_manifest_subjects(a);
    });
    p.mode = a.loso ? HarMode::loso : several(a) ? HarMode::several_sets : HarMode::one_set;
    p.train = a.train, p.test = a.test, p.out = a.out;
    p.folds = a.folds, p.sets = a.sets, p.options = a.options;
    return p;
}

void run(const HarRunPlan& p) {
    const auto windows_of = [&](const std::string& set, const WindowOptions& options) {
        WindowSet ws = make_windows(read_imu_dataset(set), options);
        return p.keep.empty() ? ws : relabel(ws, p.keep);
    };
    HarResult result;
    std::string description;
    if (p.mode == HarMode::loso) {
        result = leave_one_subject_out(windows_of(p.train[0], p.train_windows), p.options, p.folds);
        description =
            (p.folds > 0 ? std::to_string(p.folds) + "-fold leave-subjects-out on " : "leave-one-subject-out on ") +
            p.train[0];
    } else if (p.mode == HarMode::one_set) {
        result = train_and_test(windows_of(p.train[0], p.train_windows),
                                make_windows(read_imu_dataset(p.test), p.test_windows), p.options);
        description = "trained on " + p.train[0] + ", tested on " + p.test;
    } else {
        const WindowSet test = windows_of(p.test, p.test_windows);
        std::vector<WindowSet> sets;
        sets.reserve(p.train.size());
        std::vector<TrainingSet> train;
        for (size_t i = 0; i < p.train.size(); ++i) {
            if (static_cast<int>(i) != p.sets.test_set) sets.push_back(windows_of(p.train[i], p.train_windows));
            train.push_back({static_cast<int>(i) == p.sets.test_set ? &test : &sets.back(), p.train[i]});
        }
        result = train_on_sets(train, test, p.options, p.sets);
        description = std::string(har_protocol_name(p.sets.protocol)) + ": trained on " + join(p.train, " + ") +
                      ", tested on " + p.test +
                      (p.sets.test_set >= 0
                           ? " less the " + std::to_string(p.sets.train_subjects) + " subjects drawn for each training"
                           : "");
    }
    write_file_atomic(p.out, har_result_json(result, description));
    double mean = 0;
    for (const HarRun& r : result.runs) mean += r.balanced_accuracy / static_cast<double>(result.runs.size());
    std::printf("%s: balanced accuracy %.4f over %zu runs, %zu classes, %zu train / %zu test windows\n", p.out.c_str(),
                mean, result.runs.size(), result.classes.size(), result.train_windows, result.test_windows);
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& har = command_group(root, "har", "human activity recognition on IMU datasets");
    auto* cmd =
        har.add_subcommand("run", "train DeepConvLSTM on --train, test on --test (or --loso); writes RESULT.json");
    auto& a = option_values<HarArgs>();
    cmd->add_option("--train", a.train,
                    "training dataset (manifest.csv layout); repeat it to train on several together")
        ->required()
        ->check(CLI::ExistingDirectory)
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    cmd->add_option("--test", a.test, "test dataset")->check(CLI::ExistingDirectory);
    cmd->add_flag("--loso", a.loso, "leave-one-subject-out on --train instead of a test set");
    cmd->add_option("--positions", a.positions,
                    "training positions, comma-separated (a name without side matches either side)");
    cmd->add_option("--test-positions", a.test_positions, "test positions, in the order of --positions");
    cmd->add_option("--channels", a.channels, "acc or acc,gyr");
    cmd->add_option("--rate", a.windows.rate_hz, "evaluation rate, Hz");
    cmd->add_option("--window", a.windows.window_s, "window length, s");
    cmd->add_option("--overlap", a.windows.overlap, "window overlap, 0..1");
    cmd->add_option("--folds", a.folds, "with --loso: subjects dealt into this many folds (default: one per subject)");
    cmd->add_option("--train-subjects", a.train_subjects,
                    "draw this many subjects of the --train set that is also --test (seeded by --seed and the repeat); "
                    "the others are tested");
    cmd->add_option("--train-share", a.train_share,
                    "share of each batch per --train, comma-separated in --train order (default: by windows); with "
                    "finetune, of each fine-tuning batch (default: the drawn subjects alone)");
    cmd->add_option("--protocol", a.protocol,
                    "several sets: mix (one training on all) or finetune (train on the others, then fine-tune on the "
                    "drawn subjects)");
    cmd->add_option("--finetune-epochs", a.sets.finetune_epochs,
                    "finetune: most fine-tuning epochs (early stopping; 0 = the pretrained network)");
    cmd->add_option("--finetune-lr", a.sets.finetune_learning_rate, "finetune: the fine-tuning's learning rate");
    cmd->add_option("--classes", a.classes, "keep only these training classes (after the data set's class map)");
    cmd->add_option("--repeats", a.options.repeats, "trainings with consecutive seeds");
    cmd->add_option("--epochs", a.options.max_epochs, "most epochs per training (early stopping, patience 5)");
    cmd->add_option("--seed", a.options.seed, "first seed");
    cmd->add_option("--out", a.out, "RESULT.json")->required();
    cmd->callback([&a] { run(plan_har_run(a)); });
});

}  // namespace t2imu::cli
