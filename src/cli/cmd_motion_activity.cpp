// t2imu motion activity: the motion activity classifier (motion/motion_activity.hpp) — build its reference from
// a dataset's captured clips, validate it leave-one-subject-out, and classify what `t2imu synth` generated:
// the confusion of prompt activity against the activity the motion shows.
#include <algorithm>
#include <cstdio>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "data/activity_reference.hpp"
#include "report/activity_confusion.hpp"

namespace t2imu::cli {

namespace {

struct ActivityArgs {
    std::string dataset, reference, synth, save_reference, out;
};

// Prints the table and the share shown as their activity; with `csv`, writes the table.
void report(const ActivityConfusion& t, const std::string& csv) {
    const std::string text = t.csv();
    std::printf("%s%ld of %ld checkable motions shown as their activity\n", text.c_str(), t.right(), t.total());
    if (!csv.empty()) write_file_atomic(csv, text);
}

void validate(const MotionActivityClassifier& c, const std::string& csv) {
    std::vector<double> agreement;
    std::printf("leave-one-subject-out over the reference clips:\n");
    report(reference_confusion(c, &agreement), csv);
    std::sort(agreement.begin(), agreement.end());
    const auto at = [&](double p) {
        return agreement[static_cast<size_t>(p * static_cast<double>(agreement.size() - 1))];
    };
    std::printf("agreement of a clip with its own activity: 0.5th percentile %.3f, 5th %.3f, median %.3f\n", at(0.005),
                at(0.05), at(0.5));
}

void classify_synth(const MotionActivityClassifier& c, const std::string& dir, const std::string& csv) {
    const ActivityConfusion t = synth_confusion(c, dir);
    std::string mapping;
    for (size_t i = 0; i < t.rows.size(); ++i)
        mapping += (i ? ", " : "") + t.rows[i] + " -> " +
                   (t.expected[i].empty() ? std::string("(none: not checked)") : t.expected[i]);
    std::printf(
        "prompted activity (rows) against the activity shown (columns), %s; the classifier's class for each\n"
        "prompted one: %s\n",
        dir.c_str(), mapping.c_str());
    report(t, csv);
}

void run(const ActivityArgs& a) {
    check_usage([&] {
        if (a.dataset.empty() == a.reference.empty())
            throw Error("motion activity", "reference", "either --dataset DIR or --reference CSV");
        if (!a.save_reference.empty())
            check_output(a.save_reference, "--save-reference", OutputKind::file, {a.dataset, a.reference, a.synth});
        if (!a.out.empty())
            check_output(a.out, "--out", OutputKind::file, {a.dataset, a.reference, a.synth, a.save_reference});
    });
    const MotionActivityClassifier c = a.dataset.empty() ? MotionActivityClassifier::load(a.reference)
                                                         : MotionActivityClassifier(activity_examples(a.dataset));
    if (!a.save_reference.empty()) {
        write_csv(a.save_reference, c.reference_table());
        std::printf("%s: %zu clips of %zu activities\n", a.save_reference.c_str(), c.reference_table().rows.size(),
                    c.classes().size());
    }
    if (a.synth.empty())
        validate(c, a.out);
    else
        classify_synth(c, a.synth, a.out);
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& motion = command_group(root, "motion", "motion files: import, export, HumanML3D features");
    auto* cmd = motion.add_subcommand(
        "activity",
        "motion activity classifier: build its reference, validate it, or classify a synth folder's motions");
    auto& a = option_values<ActivityArgs>();
    cmd->add_option("--dataset", a.dataset, "dataset built by t2imu data build: its captured clips are the reference")
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--reference", a.reference, "reference CSV (models/motion-activity.csv)")->check(CLI::ExistingFile);
    cmd->add_option("--save-reference", a.save_reference, "write the reference CSV");
    cmd->add_option("--synth", a.synth,
                    "t2imu synth folder: confusion of prompted against shown activity (else: leave-one-subject-out on "
                    "the reference)")
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--out", a.out, "confusion CSV");
    cmd->callback([&a] { run(a); });
});

}  // namespace t2imu::cli
