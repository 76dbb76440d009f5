// t2imu data reframe: an IMU dataset's recordings put into another data set's sensor axes (imu/reframe.hpp),
// so that real data sets can be compared with each other window by window as synthetic data is with real.
// The source convention is --from, else each recording's `frame` column (a reframed dataset), else its
// `dataset` column (a real data set's importer names it: a data set profile's name, imu/dataset_profile.hpp).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>

#include "body/body_model.hpp"
#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "core/parse.hpp"
#include "imu/dataset_profile.hpp"
#include "imu/reframe.hpp"

namespace t2imu::cli {

namespace fs = std::filesystem;

namespace {

struct ReframeArgs {
    std::string dataset, from, to, positions, out;
};

void write_dataset(const ReframeArgs& a, const std::vector<ImuRecording>& recordings) {
    remove_stale_partials(a.out);
    const fs::path tmp = partial_path_for(a.out);
    fs::remove_all(tmp);
    write_imu_dataset(tmp.string(), recordings, 6);
    publish_partial(tmp.string(), a.out);
}

void run(const ReframeArgs& a) {
    PlacementSet to, from;
    check_usage([&] {
        to = placement_set_named(a.to, "--to");
        if (!a.from.empty()) from = placement_set_named(a.from, "--from");
        check_output(a.out, "--out", OutputKind::folder, {a.dataset, a.to, a.from});
    });
    const std::vector<ImuRecording> recordings =
        reframe_dataset(a.dataset, split_list(a.positions), to, a.from.empty() ? nullptr : &from);
    write_dataset(a, recordings);
    std::printf("%s: %zu recordings in the axes of %s\n", a.out.c_str(), recordings.size(), to.name.c_str());
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& data = command_group(root, "data", "training and IMU datasets");
    auto* cmd = data.add_subcommand("reframe",
                                    "an IMU dataset's sensors in another data set's axes (to compare real data sets)");
    auto& a = option_values<ReframeArgs>();
    cmd->add_option("dataset", a.dataset, "IMU dataset folder (manifest.csv layout)")
        ->required()
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--to", a.to, "target axes: " + dataset_profile_names() + " or a placement FILE.toml")->required();
    cmd->add_option("--from", a.from, "source axes (default: each recording's frame, else its dataset column)");
    cmd->add_option("--positions", a.positions, "positions to keep, comma-separated (default: all)");
    cmd->add_option("--out", a.out, "output dataset folder")->required();
    cmd->callback([&a] { run(a); });
});

}  // namespace t2imu::cli
