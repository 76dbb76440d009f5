#include "data/clip_activities.hpp"

#include <filesystem>
#include <sstream>

#include "core/csv.hpp"
#include "motion/activity_names.hpp"

namespace t2imu {

std::map<std::string, std::vector<std::string>> read_clip_activities(const std::string& dataset) {
    std::map<std::string, std::vector<std::string>> out;
    const std::string path = dataset + "/clips.csv";
    if (!std::filesystem::exists(path)) return out;
    const CsvTable t = read_csv(path);
    const size_t id = t.column("id"), tags = t.column("activity_tags");
    for (const auto& row : t.rows) {
        std::stringstream in(row[tags]);
        std::string tag;
        while (std::getline(in, tag, ';'))
            if (!tag.empty()) out[row[id]].push_back(canonical_activity(tag));
    }
    return out;
}

std::string clip_file_id(const std::string& id) { return id.substr(0, id.find('#')); }

}  // namespace t2imu
