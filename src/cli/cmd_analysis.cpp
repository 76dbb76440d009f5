// t2imu analysis domain-gap: real against synthetic catch22 tables, the classifier two-sample test and
// per-feature distances.
#include <cstdio>

#include "analysis/domain_gap.hpp"
#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/output_path.hpp"

namespace t2imu::cli {

static void add_domain_gap(CLI::App& analysis) {
    auto* cmd = analysis.add_subcommand(
        "domain-gap", "two catch22 tables (real, synthetic) -> two-sample test and per-feature distances (JSON)");
    auto& real = option_values<std::string>();
    auto& synthetic = option_values<std::string>();
    auto& out = option_values<std::string>();
    auto& classes = option_values<std::vector<std::string>>();
    auto& seed = option_values<uint64_t>(0);
    cmd->add_option("--real", real, "features of real windows (t2imu features catch22 --dataset)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--synthetic", synthetic, "features of synthetic windows (or of a second real data set)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--classes", classes, "only windows of these activities, in both tables (comma-separated)")
        ->delimiter(',');
    cmd->add_option("--seed", seed, "fold assignment seed");
    cmd->add_option("--out", out, "RESULT.json")->required();
    cmd->callback([&classes, &out, &real, &seed, &synthetic] {
        check_usage([&classes, &out, &real, &seed, &synthetic] {
            check_output(out, "--out", OutputKind::file, {real, synthetic});
        });
        CsvTable r = read_csv(real), s = read_csv(synthetic);
        if (!classes.empty()) {
            r = rows_of_activities(r, classes, "--classes");
            s = rows_of_activities(s, classes, "--classes");
        }
        const DomainGap gap = domain_gap(r, s, seed);
        write_file_atomic(out, domain_gap_json(gap).dump(2) + "\n");
        std::printf("%s: two-sample balanced accuracy %.3f (0.5 = indistinguishable) over %lld features\n", out.c_str(),
                    gap.overall.balanced_accuracy, static_cast<long long>(gap.features));
    });
}

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& analysis = command_group(root, "analysis", "evaluation analyses");
    add_domain_gap(analysis);
});

}  // namespace t2imu::cli
