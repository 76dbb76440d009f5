#include "har/class_map.hpp"

#include <map>

#include "imu/dataset_profile.hpp"

namespace t2imu {

std::string map_activity(const std::string& dataset, const std::string& activity) {
    static const std::map<std::string, std::string> synthetic = {{"jogging", "running"}, {"stairs_up_down", "stairs"}};
    const DatasetProfile* profile = find_dataset_profile(dataset);
    const std::map<std::string, std::string>* map = dataset == "t2imu" ? &synthetic
                                                    : profile          ? &profile->class_map
                                                                       : nullptr;
    if (!map) return activity;
    const auto a = map->find(activity);
    return a == map->end() ? activity : a->second;
}

std::string coarsen_for(const std::string& label, const std::set<std::string>& this_side,
                        const std::set<std::string>& other_side) {
    const bool fine = label == "stairs_up" || label == "stairs_down";
    const bool other_coarse = other_side.count("stairs") > 0, this_coarse = this_side.count("stairs") > 0;
    if (fine && (other_coarse || this_coarse)) return "stairs";
    return label;
}

}  // namespace t2imu
