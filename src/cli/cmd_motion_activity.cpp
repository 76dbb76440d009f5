// t2imu motion activity: the motion activity classifier (motion/motion_activity.hpp) — build its reference from
// a dataset's captured clips, validate it leave-one-subject-out, and classify what `t2imu synth` generated:
// the confusion of prompt activity against the activity the motion shows.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/json_file.hpp"
#include "core/npy.hpp"
#include "core/output_path.hpp"
#include "data/activity_reference.hpp"
#include "motion/joint_sequence.hpp"

namespace t2imu::cli {

namespace {

struct ActivityArgs {
    std::string dataset, reference, synth, save_reference, out;
};

// Rows = true (or prompted) class, columns = predicted; `expected[r]` is row r's right column ("" = the
// classifier has no class for it: no recall, not counted). Printed and, with `csv`, written.
void print_confusion(const std::vector<std::string>& rows, const std::vector<std::string>& expected,
                     const std::vector<std::string>& columns, const std::vector<std::vector<long>>& counts,
                     const std::string& csv) {
    std::string text = "truth\\predicted";
    for (const std::string& c : columns) text += "," + c;
    text += ",recall\n";
    long right = 0, total = 0;
    for (size_t r = 0; r < rows.size(); ++r) {
        long n = 0, hit = 0;
        text += rows[r];
        for (size_t c = 0; c < columns.size(); ++c) {
            text += "," + std::to_string(counts[r][c]);
            n += counts[r][c];
            if (columns[c] == expected[r]) hit = counts[r][c];
        }
        char buf[32];
        if (expected[r].empty() || n == 0) std::snprintf(buf, sizeof buf, ",\n");
        else std::snprintf(buf, sizeof buf, ",%.3f\n", static_cast<double>(hit) / static_cast<double>(n));
        text += buf;
        if (expected[r].empty()) continue;
        right += hit;
        total += n;
    }
    std::printf("%s%ld of %ld checkable motions shown as their activity\n", text.c_str(), right, total);
    if (!csv.empty()) write_file_atomic(csv, text);
}

void validate(const MotionActivityClassifier& c, const std::string& csv) {
    std::vector<double> agreement;
    const auto confusion = c.leave_one_subject_out(&agreement);
    std::printf("leave-one-subject-out over the reference clips:\n");
    print_confusion(c.classes(), c.classes(), c.classes(), confusion, csv);
    std::sort(agreement.begin(), agreement.end());
    const auto at = [&](double p) { return agreement[static_cast<size_t>(p * static_cast<double>(agreement.size() - 1))]; };
    std::printf("agreement of a clip with its own activity: 0.5th percentile %.3f, 5th %.3f, median %.3f\n", at(0.005), at(0.05), at(0.5));
}

std::string describe_mapping(const std::vector<std::string>& prompted, const std::vector<std::string>& expected) {
    std::string s;
    for (size_t i = 0; i < prompted.size(); ++i)
        s += (i ? ", " : "") + prompted[i] + " -> " + (expected[i].empty() ? std::string("(none: not checked)") : expected[i]);
    return s;
}

// Every kept job of a synth folder: its prompt's activity against the classifier's answer.
void classify_synth(const MotionActivityClassifier& c, const std::string& dir, const std::string& csv) {
    std::vector<std::string> prompted;
    std::map<std::string, std::map<std::string, long>> counts;
    for (const auto& e : std::filesystem::directory_iterator(dir + "/jobs")) {
        if (e.path().extension() != ".json") continue;
        const std::string marker = e.path().string();
        const nlohmann::json job = read_json_file(marker);
        if (!json_bool(job, "kept", marker)) continue;
        const std::string file = dir + "/motions/" + json_string(job, "job", marker) + "_joints.npy";
        const std::string activity = json_string(job, "activity", marker);
        ++counts[activity][c.classify(describe_motion(joint_sequence_from_array(read_npy(file), file))).best];
        if (std::find(prompted.begin(), prompted.end(), activity) == prompted.end()) prompted.push_back(activity);
    }
    if (prompted.empty()) throw Error(dir + "/jobs", "jobs", "at least one kept motion");
    std::sort(prompted.begin(), prompted.end());
    std::vector<std::vector<long>> table;
    std::vector<std::string> expected;
    for (const std::string& a : prompted) {
        table.emplace_back();
        for (const std::string& k : c.classes()) table.back().push_back(counts[a][k]);
        expected.push_back(reference_activity(a, c.classes()));
    }
    std::printf("prompted activity (rows) against the activity shown (columns), %s; the classifier's class for each\n"
                "prompted one: %s\n", dir.c_str(), describe_mapping(prompted, expected).c_str());
    print_confusion(prompted, expected, c.classes(), table, csv);
}

void run(const ActivityArgs& a) {
    check_usage([&] {
        if (a.dataset.empty() == a.reference.empty()) throw Error("motion activity", "reference", "either --dataset DIR or --reference CSV");
        if (!a.save_reference.empty()) check_output_path(a.save_reference, "--save-reference");
        if (!a.out.empty()) check_output_path(a.out, "--out");
    });
    const MotionActivityClassifier c = a.dataset.empty() ? MotionActivityClassifier::load(a.reference)
                                                         : MotionActivityClassifier(activity_examples(a.dataset));
    if (!a.save_reference.empty()) {
        write_csv(a.save_reference, c.reference_table());
        std::printf("%s: %zu clips of %zu activities\n", a.save_reference.c_str(), c.reference_table().rows.size(), c.classes().size());
    }
    if (a.synth.empty()) validate(c, a.out);
    else classify_synth(c, a.synth, a.out);
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& motion = command_group(root, "motion", "motion files: import, export, HumanML3D features");
    auto* cmd = motion.add_subcommand("activity", "motion activity classifier: build its reference, validate it, or classify a synth folder's motions");
    static ActivityArgs a;
    cmd->add_option("--dataset", a.dataset, "dataset built by t2imu data build: its captured clips are the reference")->check(CLI::ExistingDirectory);
    cmd->add_option("--reference", a.reference, "reference CSV (models/motion-activity.csv)")->check(CLI::ExistingFile);
    cmd->add_option("--save-reference", a.save_reference, "write the reference CSV");
    cmd->add_option("--synth", a.synth, "t2imu synth folder: confusion of prompted against shown activity (else: leave-one-subject-out on the reference)")
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--out", a.out, "confusion CSV");
    cmd->callback([] { run(a); });
});

}  // namespace t2imu::cli
