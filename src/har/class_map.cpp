#include "har/class_map.hpp"

#include <map>

namespace t2imu {

std::string map_activity(const std::string& dataset, const std::string& activity) {
    static const std::map<std::string, std::map<std::string, std::string>> maps = {
        {"sisfall", {{"jogging", "running"}, {"stairs_up_down", "stairs"}, {"jump_reach", ""}}},
        {"umafall", {{"jogging", "running"}}},
        {"t2imu", {{"jogging", "running"}, {"stairs_up_down", "stairs"}}},
    };
    const auto d = maps.find(dataset);
    if (d == maps.end()) return activity;
    const auto a = d->second.find(activity);
    return a == d->second.end() ? activity : a->second;
}

std::string coarsen_for(const std::string& label, const std::set<std::string>& this_side, const std::set<std::string>& other_side) {
    const bool fine = label == "stairs_up" || label == "stairs_down";
    const bool other_coarse = other_side.count("stairs") > 0, this_coarse = this_side.count("stairs") > 0;
    if (fine && (other_coarse || this_coarse)) return "stairs";
    return label;
}

}  // namespace t2imu
