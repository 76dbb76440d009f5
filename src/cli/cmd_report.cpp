// t2imu report: result files -> PNG figures and a self-contained HTML page.
#include <cstdio>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/output_path.hpp"
#include "report/html_report.hpp"

namespace t2imu::cli {

static CommandRegistrar registrar([](CLI::App& root) {
    auto* cmd =
        root.add_subcommand("report", "results folder -> figures (gnuplot PNG) and index.html with them embedded");
    auto& in = option_values<std::string>();
    auto& out = option_values<std::string>();
    auto& real = option_values<std::string>();
    cmd->add_option(
           "--in", in,
           "results folder (synth_report.json, HAR RESULT.json, L_acc CSV, t-SNE CSV, domain-gap JSON, IMU CSVs)")
        ->required()
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--out", out, "report folder")->required();
    cmd->add_option(
           "--real", real,
           "a real IMU data set (manifest.csv + CSVs) whose signal statistics to show beside the synthetic ones")
        ->check(CLI::ExistingDirectory);
    cmd->callback([&in, &out, &real] {
        check_usage([&in, &out, &real] { check_output(out, "--out", OutputKind::folder, {in, real}); });
        const ReportSummary s = write_report(in, out, real);
        std::printf(
            "%s/index.html: %d figures (%d synthesis reports, %d HAR results, %d L_acc tables, %d t-SNE tables, %d "
            "domain-gap results, %d traces)\n",
            out.c_str(), s.figures, s.synth_reports, s.har_results, s.lacc_tables, s.tsne_tables, s.gap_results,
            s.traces);
    });
});

}  // namespace t2imu::cli
