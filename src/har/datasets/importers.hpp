// A data set's release folder -> its recordings in the common layout, by its profile (imu/dataset_profile.hpp):
// the profile's own importer, else the built-in reader of that name below (the readers sit here, downstream of
// the profiles' table).
#pragma once
#include <string>
#include <vector>

#include "imu/dataset_profile.hpp"

namespace t2imu {

// Whether `profile` has a reader of its release format (its own or a built-in one).
bool has_importer(const DatasetProfile& profile);
// Its recordings; files passed over are listed in `skipped` (may be null). Error naming --format without a reader.
std::vector<ImuRecording> import_imu_dataset(const DatasetProfile& profile, const std::string& folder,
                                             std::vector<std::string>* skipped);

}  // namespace t2imu
