// The activities of a dataset's clips: clips.csv's activity_tags (dataset_builder.hpp; `;`-separated) as
// canonical names (motion/activity_names.hpp), by clip id. The official HumanML3D release has no clips.csv:
// then the map is empty.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace t2imu {

std::map<std::string, std::vector<std::string>> read_clip_activities(const std::string& dataset);

// A clip id of Hml3dDataset without its caption span ("000123#0-40" -> "000123"): the row of clips.csv.
std::string clip_file_id(const std::string& id);

}  // namespace t2imu
