// t2imu analysis lacc: L_acc before/after fine-tuning per activity category (the paper's Fig. 1).
#include <cstdio>
#include <optional>

#include "analysis/lacc_analysis.hpp"
#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"

namespace t2imu::cli {

namespace {

struct LaccArgs {
    std::string before, after, vocab, labels, out;
    std::optional<double> tau;  // a cosine similarity threshold; else calibrated on --labels
};

void run(const LaccArgs& a) {
    check_usage([&] {
        if (a.tau && !(*a.tau >= -1 && *a.tau <= 1))
            throw Error("--tau", "tau", "a cosine similarity from -1 to 1", std::to_string(*a.tau));
        if (!a.tau && a.labels.empty()) throw Error("--tau", "tau", "--tau T or --labels CSV to calibrate it");
        check_output(a.out, "--out", OutputKind::file, {a.before, a.after, a.vocab, a.labels});
    });
    const WordVectors vectors = WordVectors::load(a.vocab);
    const SifEncoder sif(vectors, kCategorySifWeight);
    const std::vector<LaccSample> before = read_lacc_csv(a.before), after = read_lacc_csv(a.after);
    double tau = a.tau.value_or(0);
    if (!a.tau) {
        const CsvTable t = read_csv(a.labels);
        std::vector<std::string> captions, labels;
        for (const auto& row : t.rows)
            captions.push_back(row[t.column("caption")]), labels.push_back(row[t.column("category")]);
        const TauCalibration c = calibrate_tau(sif, captions, labels);
        std::printf("tau %.2f: %.1f %% agreement with %zu labelled captions\n", c.tau, 100 * c.agreement, c.captions);
        tau = c.tau;
    }
    const LaccAnalysis analysis = analyse_lacc(before, after, ActivityCategorizer(sif, tau));
    write_file_atomic(a.out, lacc_analysis_csv(analysis));
    std::printf("%s: L_acc change %.2f %% over %zu samples (high-dynamic %.2f %%, low-dynamic %.2f %%)\n",
                a.out.c_str(), analysis.all.change_percent(), analysis.all.samples,
                analysis.high_dynamic.change_percent(), analysis.low_dynamic.change_percent());
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& analysis = command_group(root, "analysis", "evaluation analyses");
    auto* cmd = analysis.add_subcommand(
        "lacc", "per-sample L_acc of two models (id,caption,l_acc) -> change per activity category");
    auto& a = option_values<LaccArgs>();
    cmd->add_option("--before", a.before, "L_acc CSV of the base model")->required()->check(CLI::ExistingFile);
    cmd->add_option("--after", a.after, "L_acc CSV of the fine-tuned model")->required()->check(CLI::ExistingFile);
    cmd->add_option("--vocab", a.vocab, "GloVe vocabulary (cache/text/glove-100k.safetensors)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--tau", a.tau, "similarity threshold for Other");
    cmd->add_option("--labels", a.labels, "caption,category CSV to calibrate tau on");
    cmd->add_option("--out", a.out, "output CSV: group,samples,l_acc_before,l_acc_after,change_percent")->required();
    cmd->callback([&a] { run(a); });
});

}  // namespace t2imu::cli
