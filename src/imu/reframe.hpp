// One data set's sensor axes expressed in another's: the rotation between two placement conventions
// (placement.hpp) at the same position, and a recording turned by it. With it a real data set can be put
// into the axes of another (UMAFall's waist tag, x up, into SisFall's belt board, y down, z forward) and the
// two compared window by window, as synthetic data is compared with real.
//
// Both placements are mounted on one body standing at rest (procedural_body.hpp's default unless given); the
// rotation is sensor_to <- sensor_from. Skin-relative axis words ("out", "distal") resolve on that body, so two
// conventions that differ only by naming ("out" at the front of the waist against "front") give an exact axis
// permutation wherever the body is left-right symmetric about the sensor.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "body/body_model.hpp"
#include "imu/imu_dataset.hpp"
#include "imu/placement.hpp"

namespace t2imu {

// sensor_to <- sensor_from for `from` and `to` mounted on `body` at rest (no mounting error, no tilt).
Eigen::Matrix3d reframe_rotation(const BodyModel& body, const SensorPlacement& from, const SensorPlacement& to);

// Every sample's acceleration and angular rate turned by `to_from`; times and every other field unchanged.
void reframe_recording(const Eigen::Matrix3d& to_from, ImuRecording& recording);

// A data set's placement set by its name (dataset_profile.hpp) or a placement TOML file; Error naming `option` for
// another name.
PlacementSet placement_set_named(const std::string& text, const std::string& option);

// The recordings of the IMU dataset folder `dataset` (those at `positions`, every one when empty) turned into `to`'s
// axes from `from`'s, or when `from` is null from the convention each recording names: its `frame` column (a
// reframed dataset), else its `dataset` column (a data set's profile). Every rotation is resolved, so every
// convention and position checked, before any samples are read; each recording's `frame` column becomes to.name.
std::vector<ImuRecording> reframe_dataset(const std::string& dataset, const std::vector<std::string>& positions,
                                          const PlacementSet& to, const PlacementSet* from);

// The placement of `position` in `set`; throws Error naming `option` with the set's positions if it has none.
const SensorPlacement& placement_at(const PlacementSet& set, const std::string& position, const std::string& option);

}  // namespace t2imu
