// t2imu data reframe: an IMU dataset's recordings put into another data set's sensor axes (imu/reframe.hpp),
// so that real data sets can be compared with each other window by window as synthetic data is with real.
// The source convention is --from, else each recording's `frame` column (a reframed dataset), else its
// `dataset` column (a real data set's importer names it: sisfall, umafall, hugadb, realworld).
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
#include "imu/reframe.hpp"

namespace t2imu::cli {

namespace fs = std::filesystem;

namespace {

struct ReframeArgs {
    std::string dataset, from, to, positions, out;
};

// A built-in placement set by name or a TOML file; an unknown name is refused naming `option`.
PlacementSet placement_set(const std::string& text, const std::string& option) {
    if (text.size() > 5 && ends_with(text, ".toml")) return read_placement_toml(text);
    const std::vector<std::string>& names = builtin_placement_set_names();
    if (std::find(names.begin(), names.end(), text) == names.end())
        throw Error(option, "set", "realworld, sisfall, umafall, hugadb or a .toml file", text);
    return builtin_placement_set(text);
}

// The recordings to turn (--positions, else all), checked against the dataset before any samples are read.
std::vector<ImuRecording> selected_recordings(const ReframeArgs& a) {
    std::vector<ImuRecording> all = read_imu_dataset(a.dataset, false), kept;
    const std::vector<std::string> listed = split_list(a.positions);
    const std::set<std::string> wanted(listed.begin(), listed.end());
    std::set<std::string> held;
    for (ImuRecording& r : all) {
        held.insert(r.position);
        if (wanted.empty() || wanted.count(r.position)) kept.push_back(std::move(r));
    }
    for (const std::string& p : wanted)
        if (!held.count(p)) throw Error("--positions", p, "a position the data set holds");
    return kept;
}

// The convention a recording is in when --from is not given: its `frame` (a reframed dataset) or its `dataset`.
PlacementSet recorded_set(const ReframeArgs& a, const ImuRecording& r) {
    const auto frame = r.extra.find("frame");
    const std::string name = frame != r.extra.end() && !frame->second.empty() ? frame->second : r.dataset;
    const std::vector<std::string>& names = builtin_placement_set_names();
    if (std::find(names.begin(), names.end(), name) == names.end())
        throw Error(a.dataset + "/manifest.csv", r.path + " dataset",
                    "a placement set's name (realworld, sisfall, umafall, hugadb), or --from", name);
    return builtin_placement_set(name);
}

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
        to = placement_set(a.to, "--to");
        if (!a.from.empty()) from = placement_set(a.from, "--from");
        check_output(a.out, "--out", OutputKind::folder, {a.dataset, a.to, a.from});
    });
    // Every rotation is resolved, so every convention checked, before any samples are read or written.
    const std::unique_ptr<BodyModel> body = make_body(parse_body_specs("preset:male_average")[0]);
    std::vector<ImuRecording> recordings = selected_recordings(a);
    std::vector<Eigen::Matrix3d> rotations;
    for (const ImuRecording& r : recordings) {
        const bool recorded = a.from.empty();
        const SensorPlacement source = recorded ? placement_at(recorded_set(a, r), r.position, a.dataset + "/manifest.csv " + r.path)
                                                 : placement_at(from, r.position, "--from");
        rotations.push_back(reframe_rotation(*body, source, placement_at(to, r.position, "--to")));
    }
    const std::vector<ImuRecording> loaded = read_imu_dataset(a.dataset);
    for (size_t i = 0, k = 0; i < loaded.size() && k < recordings.size(); ++i) {
        if (loaded[i].path != recordings[k].path) continue;
        recordings[k].t = loaded[i].t;
        recordings[k].samples = loaded[i].samples;
        reframe_recording(rotations[k], recordings[k]);
        recordings[k].extra["frame"] = to.name;
        ++k;
    }
    write_dataset(a, recordings);
    std::printf("%s: %zu recordings in the axes of %s\n", a.out.c_str(), recordings.size(), to.name.c_str());
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& data = command_group(root, "data", "training and IMU datasets");
    auto* cmd = data.add_subcommand("reframe", "an IMU dataset's sensors in another data set's axes (to compare real data sets)");
    static ReframeArgs a;
    cmd->add_option("dataset", a.dataset, "IMU dataset folder (manifest.csv layout)")->required()->check(CLI::ExistingDirectory);
    cmd->add_option("--to", a.to, "target axes: realworld, sisfall, umafall, hugadb or a placement FILE.toml")->required();
    cmd->add_option("--from", a.from, "source axes (default: each recording's frame, else its dataset column)");
    cmd->add_option("--positions", a.positions, "positions to keep, comma-separated (default: all)");
    cmd->add_option("--out", a.out, "output dataset folder")->required();
    cmd->callback([] { run(a); });
});

}  // namespace t2imu::cli
