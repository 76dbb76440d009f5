// t2imu features catch22: the catch22 (or catch24) features of one series, printed like the reference C
// program ("value, NAME" per line, in its output order, %.14f), or of every window of a dataset into a CSV.
#include <cstdio>
#include <set>

#include "analysis/catch22.hpp"
#include "analysis/catch22_table.hpp"
#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "core/parse.hpp"

namespace t2imu::cli {

static void add_catch22_command(CLI::App& features) {
    auto* cmd = features.add_subcommand(
        "catch22", "catch22 of a series (--in), or of every window and channel of a dataset (--dataset)");
    auto& in = option_values<std::string>();
    auto& dataset = option_values<std::string>();
    auto& out = option_values<std::string>();
    auto& positions = option_values<std::string>();
    auto& catch24 = option_values<bool>(false);
    auto& w = option_values<WindowOptions>();
    cmd->add_option("--in", in, "series file: whitespace-separated numbers")->check(CLI::ExistingFile);
    cmd->add_option("--dataset", dataset, "IMU dataset (manifest.csv layout): batch mode")
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--out", out, "batch mode: output CSV");
    cmd->add_option("--positions", positions, "batch mode: positions, comma-separated (default: the only one)");
    cmd->add_option("--rate", w.rate_hz, "batch mode: window rate, Hz");
    cmd->add_option("--window-s", w.window_s, "batch mode: window length, s");
    cmd->add_option("--overlap", w.overlap, "batch mode: overlap");
    cmd->add_flag("--gyro", w.gyro, "batch mode: gyroscope channels too");
    cmd->add_flag("--catch24", catch24, "add DN_Mean and DN_Spread_Std (catch24)");
    cmd->callback([&catch24, &dataset, &in, &out, &w, &positions] {
        if (in.empty() == dataset.empty())
            throw Error("features catch22", "input", "either --in SERIES.txt or --dataset DIR");
        if (!in.empty()) {
            const std::vector<double> values = catch22(read_catch22_series(in), catch24, in);
            for (std::size_t index : catch22_reference_output_order(catch24))
                std::printf("%.14f, %s\n", values[index], catch24_names()[index].c_str());
            return;
        }
        if (out.empty()) throw Error("features catch22", "--out", "an output CSV in batch mode");
        w.window_option = "--window-s";
        w.min_window_samples = static_cast<long>(kCatch22MinLength);  // shorter windows give every feature nan
        check_usage([&catch24, &dataset, &in, &out, &positions, &w] {
            w.validate();
            check_output(out, "--out", OutputKind::file, {in, dataset});
        });
        w.positions = split_list(positions);
        const std::vector<ImuRecording> recordings = read_imu_dataset(dataset);
        if (w.positions.empty() && !recordings.empty()) {
            std::set<std::string> all;
            for (const ImuRecording& r : recordings) all.insert(r.position);
            if (all.size() == 1) w.positions = {*all.begin()};  // name the columns after it
        }
        const WindowSet windows = make_windows(recordings, w);
        write_csv(out, catch22_window_table(windows, window_channel_names(w), catch24, worker_threads()));
        std::printf("%s: %zu windows x %d channels\n", out.c_str(), windows.size(), windows.channels);
    });
}

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& features = command_group(root, "features", "time-series features of IMU signals (catch22)");
    add_catch22_command(features);
});

}  // namespace t2imu::cli
