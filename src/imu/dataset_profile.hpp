// The real HAR data sets, one profile each, and the one table every other table draws from: the placement sets
// (--sensors, data reframe --to/--from), the sensor models (the realism table's sensor key), the realism
// presets (--realism), the class maps (har/class_map.hpp), data import-imu's --format and the help texts that list
// them. Adding a data set is one entry in dataset_profile.cpp plus its importer (docs/overview.md, "Adding a data
// set"); a program or a test may add its own profile at run time (add_dataset_profile).
//
// Placements and axes follow placement.hpp's words; the sources of each (what the release documents, what was
// estimated from its data) are in the entries' notes and in placement.hpp.
#pragma once
#include <deque>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "imu/imu_dataset.hpp"
#include "imu/placement.hpp"
#include "imu/sensor_noise.hpp"

namespace t2imu {

// A release folder -> its recordings in the common layout (imu_dataset.hpp); files passed over are listed in
// `skipped` (which may be null).
using ImuImporter =
    std::function<std::vector<ImuRecording>(const std::string& folder, std::vector<std::string>* skipped)>;

struct DatasetProfile {
    std::string name;   // the manifest's dataset column, and the name --sensors, --realism, --format and --to take
    std::string about;  // one line for help texts: the recording device and where it sat
    std::vector<SensorPlacement> placements;        // its sensors' placements and axes
    SensorNoiseModel sensor;                        // its device's errors (named after the data set)
    double tilt_mean_deg = 0, tilt_spread_deg = 0;  // its realism preset's mounting tilt (realism.hpp), degrees
    std::map<std::string, std::string> class_map;   // its activity label -> the evaluation class ("" = dropped)
    // Its release format's reader. The built-in data sets' readers sit downstream in har/datasets/ and are found
    // by name there (har/datasets/importers.hpp); a profile added at run time brings its own.
    ImuImporter importer;
};

// Every profile: the built-in ones (realworld, sisfall, umafall, hugadb), then those added (a deque: adding one
// leaves references to the others valid).
const std::deque<DatasetProfile>& dataset_profiles();
// The profile of that name, or null.
const DatasetProfile* find_dataset_profile(const std::string& name);
// "realworld, sisfall, umafall, hugadb" (and any added): for help texts and the "expected" part of errors.
std::string dataset_profile_names();
// Throws Error naming the profile and the part it lacks (a name, an about line, placements with two axes each, a
// sensor model, a tilt within the realism table's ranges), or a name already taken.
void check_dataset_profile(const DatasetProfile& profile);
// Adds a data set of the caller's own (checked as above; it must bring its importer); every table sees it from then on.
void add_dataset_profile(DatasetProfile profile);
// Removes an added profile (a test's, when it is done with it); the built-in ones stay.
void remove_dataset_profile(const std::string& name);

}  // namespace t2imu
