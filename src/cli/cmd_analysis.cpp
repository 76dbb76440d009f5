// t2imu analysis lacc: L_acc before/after fine-tuning per activity category (the paper's Fig. 1).
#include <cstdio>
#include <optional>

#include "analysis/domain_gap.hpp"
#include "analysis/lacc_analysis.hpp"
#include "analysis/signal_statistics.hpp"
#include "analysis/static_segments.hpp"
#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "imu/imu_dataset.hpp"

namespace t2imu::cli {

namespace {

struct LaccArgs {
    std::string before, after, vocab, labels, out;
    std::optional<double> tau;  // a cosine similarity threshold; else calibrated on --labels
};

void run(const LaccArgs& a) {
    check_usage([&] {
        if (a.tau && !(*a.tau >= -1 && *a.tau <= 1)) throw Error("--tau", "tau", "a cosine similarity from -1 to 1", std::to_string(*a.tau));
        if (!a.tau && a.labels.empty()) throw Error("--tau", "tau", "--tau T or --labels CSV to calibrate it");
        check_output_path(a.out, "--out");
    });
    const WordVectors vectors = WordVectors::load(a.vocab);
    const SifEncoder sif(vectors, kCategorySifWeight);
    const std::vector<LaccSample> before = read_lacc_csv(a.before), after = read_lacc_csv(a.after);
    double tau = a.tau.value_or(0);
    if (!a.tau) {
        const CsvTable t = read_csv(a.labels);
        std::vector<std::string> captions, labels;
        for (const auto& row : t.rows) captions.push_back(row[t.column("caption")]), labels.push_back(row[t.column("category")]);
        const TauCalibration c = calibrate_tau(sif, captions, labels);
        std::printf("tau %.2f: %.1f %% agreement with %zu labelled captions\n", c.tau, 100 * c.agreement, c.captions);
        tau = c.tau;
    }
    const LaccAnalysis analysis = analyse_lacc(before, after, ActivityCategorizer(sif, tau));
    write_file_atomic(a.out, lacc_analysis_csv(analysis));
    std::printf("%s: L_acc change %.2f %% over %zu samples (high-dynamic %.2f %%, low-dynamic %.2f %%)\n", a.out.c_str(),
                analysis.all.change_percent(), analysis.all.samples, analysis.high_dynamic.change_percent(), analysis.low_dynamic.change_percent());
}

}  // namespace

static void add_domain_gap(CLI::App& analysis) {
    auto* cmd = analysis.add_subcommand("domain-gap", "two catch22 tables (real, synthetic) -> two-sample test and per-feature distances (JSON)");
    static std::string real, synthetic, out;
    static std::vector<std::string> classes;
    static uint64_t seed = 0;
    cmd->add_option("--real", real, "features of real windows (t2imu features catch22 --dataset)")->required()->check(CLI::ExistingFile);
    cmd->add_option("--synthetic", synthetic, "features of synthetic windows (or of a second real data set)")->required()->check(CLI::ExistingFile);
    cmd->add_option("--classes", classes, "only windows of these activities, in both tables (comma-separated)")->delimiter(',');
    cmd->add_option("--seed", seed, "fold assignment seed");
    cmd->add_option("--out", out, "RESULT.json")->required();
    cmd->callback([] {
        check_usage([] { check_output_path(out, "--out"); });
        CsvTable r = read_csv(real), s = read_csv(synthetic);
        if (!classes.empty()) {
            r = rows_of_activities(r, classes, "--classes");
            s = rows_of_activities(s, classes, "--classes");
        }
        const nlohmann::json gap = domain_gap(r, s, seed);
        write_file_atomic(out, gap.dump(2) + "\n");
        std::printf("%s: two-sample balanced accuracy %.3f (0.5 = indistinguishable) over %d features\n", out.c_str(),
                    gap["classifier_two_sample_test"]["balanced_accuracy"].get<double>(), gap["features"].get<int>());
    });
}

static void add_signal_stats(CLI::App& analysis) {
    auto* cmd = analysis.add_subcommand("signal-stats", "per-activity accelerometer statistics of IMU data sets (level, spectrum, tilt), real beside synthetic (JSON)");
    static std::string real, synthetic, out;
    static SignalStatisticsOptions o;
    cmd->add_option("--real", real, "an IMU data set folder (manifest.csv)")->required()->check(CLI::ExistingDirectory);
    cmd->add_option("--synthetic", synthetic, "a second data set to compare with --real (synthetic)")->check(CLI::ExistingDirectory);
    cmd->add_option("--position", o.position, "only this position (waist); default: every position");
    cmd->add_option("--rate", o.rate_hz, "resample to this rate first, Hz (HAR's)");
    cmd->add_option("--out", out, "RESULT.json")->required();
    cmd->callback([] {
        check_usage([] {
            o.validate();
            check_output_path(out, "--out");
        });
        const std::vector<ImuRecording> r = read_imu_dataset(real);
        const nlohmann::json stats = synthetic.empty() ? activity_signal_statistics(r, o) : compare_signal_statistics(r, read_imu_dataset(synthetic), o);
        write_file_atomic(out, stats.dump(2) + "\n");
        std::printf("%s: statistics of %zu activities\n", out.c_str(), stats.size());
    });
}

static void add_static_noise(CLI::App& analysis) {
    auto* cmd = analysis.add_subcommand("static-noise", "device errors from the quietest window of each real recording (noise, gyro offset, |g| error), beside a device model's (JSON)");
    static std::string real, noise = "none", out;
    static StaticNoiseOptions o;
    cmd->add_option("--real", real, "an IMU data set folder (manifest.csv)")->required()->check(CLI::ExistingDirectory);
    cmd->add_option("--position", o.position, "only this position (waist); default: every position");
    cmd->add_option("--window", o.window_s, "window length, s");
    cmd->add_option("--noise", noise, "a device model to set beside the measurement (as synth --noise: sisfall, umafall, ...)");
    cmd->add_option("--out", out, "RESULT.json")->required();
    cmd->callback([] {
        SensorNoiseModel device;
        check_usage([&] {
            o.validate();
            device = parse_noise_model(noise);
            check_output_path(out, "--out");
        });
        const nlohmann::json r = static_segment_noise(read_imu_dataset(real), o, device);
        write_file_atomic(out, r.dump(2) + "\n");
        const nlohmann::json& m = r["measured"];
        std::printf("%s: %d recordings at %g Hz; quietest %g s: acc sd %.4f/%.4f/%.4f m/s^2, gyr sd %.4f/%.4f/%.4f rad/s, gyr offset sd %.4f/%.4f/%.4f rad/s, ||a|-g| %.3f m/s^2\n",
                    out.c_str(), r["recordings"].get<int>(), r["rate_hz"].get<double>(), o.window_s, m["acc_sd_x"].get<double>(), m["acc_sd_y"].get<double>(),
                    m["acc_sd_z"].get<double>(), m["gyr_sd_x"].get<double>(), m["gyr_sd_y"].get<double>(), m["gyr_sd_z"].get<double>(),
                    m["gyr_offset_sd_x"].get<double>(), m["gyr_offset_sd_y"].get<double>(), m["gyr_offset_sd_z"].get<double>(), m["acc_norm_error_abs"].get<double>());
        if (r.contains("device"))
            std::printf("  %s predicts: acc sd %.4f m/s^2, gyr sd %.4f rad/s, gyr offset sd %.4f rad/s, acc offset sd %.3f m/s^2\n", noise.c_str(),
                        r["device"]["acc_sd"].get<double>(), r["device"]["gyr_sd"].get<double>(), r["device"]["gyr_offset_sd"].get<double>(),
                        r["device"]["acc_offset_sd"].get<double>());
    });
}

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& analysis = command_group(root, "analysis", "evaluation analyses");
    add_domain_gap(analysis);
    add_signal_stats(analysis);
    add_static_noise(analysis);
    auto* cmd = analysis.add_subcommand("lacc", "per-sample L_acc of two models (id,caption,l_acc) -> change per activity category");
    static LaccArgs a;
    cmd->add_option("--before", a.before, "L_acc CSV of the base model")->required()->check(CLI::ExistingFile);
    cmd->add_option("--after", a.after, "L_acc CSV of the fine-tuned model")->required()->check(CLI::ExistingFile);
    cmd->add_option("--vocab", a.vocab, "GloVe vocabulary (cache/text/glove-100k.safetensors)")->required()->check(CLI::ExistingFile);
    cmd->add_option("--tau", a.tau, "similarity threshold for Other");
    cmd->add_option("--labels", a.labels, "caption,category CSV to calibrate tau on");
    cmd->add_option("--out", a.out, "output CSV: group,samples,l_acc_before,l_acc_after,change_percent")->required();
    cmd->callback([] { run(a); });
});

}  // namespace t2imu::cli
