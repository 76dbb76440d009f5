// The captured clips of a dataset built by `t2imu data build` as examples for the motion activity classifier
// (motion/motion_activity.hpp): clips.csv's clips that carry exactly one activity tag other than "other",
// mirrored copies left out (their descriptors equal the original's), joints from new_joints/<id>.npy (20 fps).
// Derived clips (source_dataset "edited") count as the subject of the clip they were derived from.
#pragma once
#include <string>
#include <vector>

#include "motion/motion_activity.hpp"

namespace t2imu {

std::vector<ActivityExample> activity_examples(const std::string& dataset_dir);

}  // namespace t2imu
