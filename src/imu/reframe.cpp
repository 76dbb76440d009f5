#include "imu/reframe.hpp"

#include <set>

#include "body/body_spec.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"
#include "imu/dataset_profile.hpp"

namespace t2imu {

namespace {

// The recordings to turn, checked against the dataset's manifest before any samples are read.
std::vector<ImuRecording> selected_recordings(const std::string& dataset, const std::vector<std::string>& positions) {
    std::vector<ImuRecording> all = read_imu_dataset(dataset, false), kept;
    const std::set<std::string> wanted(positions.begin(), positions.end());
    std::set<std::string> held;
    for (ImuRecording& r : all) {
        held.insert(r.position);
        if (wanted.empty() || wanted.count(r.position)) kept.push_back(std::move(r));
    }
    for (const std::string& p : wanted)
        if (!held.count(p)) throw Error("--positions", p, "a position the data set holds");
    return kept;
}

// The convention a recording is in when none is given: its `frame` (a reframed dataset) or its `dataset`.
PlacementSet recorded_set(const std::string& dataset, const ImuRecording& r) {
    const auto frame = r.extra.find("frame");
    const std::string name = frame != r.extra.end() && !frame->second.empty() ? frame->second : r.dataset;
    if (!find_dataset_profile(name))
        throw Error(dataset + "/manifest.csv", r.path + " dataset",
                    "a data set's name (" + dataset_profile_names() + "), or --from", name);
    return builtin_placement_set(name);
}

}  // namespace

PlacementSet placement_set_named(const std::string& text, const std::string& option) {
    if (text.size() > 5 && ends_with(text, ".toml")) return read_placement_toml(text);
    return builtin_placement_set(text, option);
}

std::vector<ImuRecording> reframe_dataset(const std::string& dataset, const std::vector<std::string>& positions,
                                          const PlacementSet& to, const PlacementSet* from) {
    const std::unique_ptr<BodyModel> body = make_body(parse_body_specs("preset:male_average")[0]);
    std::vector<ImuRecording> recordings = selected_recordings(dataset, positions);
    std::vector<Eigen::Matrix3d> rotations;
    for (const ImuRecording& r : recordings) {
        const SensorPlacement source =
            from ? placement_at(*from, r.position, "--from")
                 : placement_at(recorded_set(dataset, r), r.position, dataset + "/manifest.csv " + r.path);
        rotations.push_back(reframe_rotation(*body, source, placement_at(to, r.position, "--to")));
    }
    const std::vector<ImuRecording> loaded = read_imu_dataset(dataset);
    for (size_t i = 0, k = 0; i < loaded.size() && k < recordings.size(); ++i) {
        if (loaded[i].path != recordings[k].path) continue;
        recordings[k].t = loaded[i].t;
        recordings[k].samples = loaded[i].samples;
        reframe_recording(rotations[k], recordings[k]);
        recordings[k].extra["frame"] = to.name;
        ++k;
    }
    return recordings;
}

Eigen::Matrix3d reframe_rotation(const BodyModel& body, const SensorPlacement& from, const SensorPlacement& to) {
    // rest_from_sensor maps sensor axes into the rest body frame; the inverse of an orthonormal frame is its
    // transpose.
    return mount_sensor(body, to).rest_from_sensor.transpose() * mount_sensor(body, from).rest_from_sensor;
}

void reframe_recording(const Eigen::Matrix3d& to_from, ImuRecording& recording) {
    for (std::array<double, 6>& s : recording.samples)
        for (int v = 0; v < 2; ++v) {  // acc xyz, then gyr xyz
            double* xyz = s.data() + 3 * v;
            const Eigen::Vector3d turned = to_from * Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
            for (int c = 0; c < 3; ++c) xyz[c] = turned[c];
        }
}

const SensorPlacement& placement_at(const PlacementSet& set, const std::string& position, const std::string& option) {
    std::string positions;
    for (const SensorPlacement& p : set.sensors) {
        if (p.position == position) return p;
        positions += (positions.empty() ? "" : ", ") + p.position;
    }
    throw Error(option, position, "a position the set " + set.name + " places (" + positions + ")");
}

}  // namespace t2imu
