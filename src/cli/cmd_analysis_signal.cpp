// t2imu analysis signal-stats | static-noise: per-activity accelerometer statistics of IMU data sets, and the
// sensor errors measured in the quietest window of each real recording.
#include <cstdio>

#include "analysis/signal_statistics.hpp"
#include "analysis/static_segments.hpp"
#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/atomic_file.hpp"
#include "core/output_path.hpp"
#include "imu/dataset_profile.hpp"
#include "imu/imu_dataset.hpp"
#include "imu/sensor_noise.hpp"

namespace t2imu::cli {

static void add_signal_stats(CLI::App& analysis) {
    auto* cmd = analysis.add_subcommand(
        "signal-stats",
        "per-activity accelerometer statistics of IMU data sets (level, spectrum, tilt), real beside synthetic (JSON)");
    auto& real = option_values<std::string>();
    auto& synthetic = option_values<std::string>();
    auto& out = option_values<std::string>();
    auto& o = option_values<SignalStatisticsOptions>();
    cmd->add_option("--real", real, "an IMU data set folder (manifest.csv)")->required()->check(CLI::ExistingDirectory);
    cmd->add_option("--synthetic", synthetic, "a second data set to compare with --real (synthetic)")
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--position", o.position, "only this position (waist); default: every position");
    cmd->add_option("--rate", o.rate_hz, "resample to this rate first, Hz (HAR's)");
    cmd->add_option("--out", out, "RESULT.json")->required();
    cmd->callback([&o, &out, &real, &synthetic] {
        check_usage([&o, &out, &real, &synthetic] {
            o.validate();
            check_output(out, "--out", OutputKind::file, {real, synthetic});
        });
        const std::vector<ImuRecording> r = read_imu_dataset(real);
        const nlohmann::json stats =
            synthetic.empty()
                ? activity_signal_statistics(r, o)
                : signal_statistics_comparison_json(compare_signal_statistics(r, read_imu_dataset(synthetic), o));
        write_file_atomic(out, stats.dump(2) + "\n");
        std::printf("%s: statistics of %zu activities\n", out.c_str(), stats.size());
    });
}

static void add_static_noise(CLI::App& analysis) {
    auto* cmd = analysis.add_subcommand("static-noise",
                                        "sensor errors from the quietest window of each real recording (noise, gyro "
                                        "offset, |g| error), beside a sensor model's (JSON)");
    auto& real = option_values<std::string>();
    auto& sensor = option_values<std::string>("none");
    auto& out = option_values<std::string>();
    auto& o = option_values<StaticNoiseOptions>();
    cmd->add_option("--real", real, "an IMU data set folder (manifest.csv)")->required()->check(CLI::ExistingDirectory);
    cmd->add_option("--position", o.position, "only this position (waist); default: every position");
    cmd->add_option("--window", o.window_s, "window length, s");
    cmd->add_option("--sensor", sensor,
                    "a sensor model to set beside the measurement (the realism model's sensor key: " +
                        dataset_profile_names() + ", smartphone)");
    cmd->add_option("--out", out, "RESULT.json")->required();
    cmd->callback([&sensor, &o, &out, &real] {
        SensorNoiseModel model;
        check_usage([&] {
            o.validate();
            model = parse_noise_model(sensor, "--sensor");
            check_output(out, "--out", OutputKind::file, {real});
        });
        const nlohmann::json r = static_segment_noise(read_imu_dataset(real), o, model);
        write_file_atomic(out, r.dump(2) + "\n");
        const nlohmann::json& m = r["measured"];
        std::printf(
            "%s: %d recordings at %g Hz; quietest %g s: acc sd %.4f/%.4f/%.4f m/s^2, gyr sd %.4f/%.4f/%.4f rad/s, gyr "
            "offset sd %.4f/%.4f/%.4f rad/s, ||a|-g| %.3f m/s^2\n",
            out.c_str(), r["recordings"].get<int>(), r["rate_hz"].get<double>(), o.window_s,
            m["acc_sd_x"].get<double>(), m["acc_sd_y"].get<double>(), m["acc_sd_z"].get<double>(),
            m["gyr_sd_x"].get<double>(), m["gyr_sd_y"].get<double>(), m["gyr_sd_z"].get<double>(),
            m["gyr_offset_sd_x"].get<double>(), m["gyr_offset_sd_y"].get<double>(), m["gyr_offset_sd_z"].get<double>(),
            m["acc_norm_error_abs"].get<double>());
        if (r.contains("sensor_model"))
            std::printf(
                "  %s predicts: acc sd %.4f m/s^2, gyr sd %.4f rad/s, gyr offset sd %.4f rad/s, acc offset sd %.3f "
                "m/s^2\n",
                sensor.c_str(), r["sensor_model"]["acc_sd"].get<double>(), r["sensor_model"]["gyr_sd"].get<double>(),
                r["sensor_model"]["gyr_offset_sd"].get<double>(), r["sensor_model"]["acc_offset_sd"].get<double>());
    });
}

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& analysis = command_group(root, "analysis", "evaluation analyses");
    add_signal_stats(analysis);
    add_static_noise(analysis);
});

}  // namespace t2imu::cli
