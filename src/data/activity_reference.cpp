#include "data/activity_reference.hpp"

#include <cstdint>
#include <nlohmann/json.hpp>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "motion/joint_sequence.hpp"

namespace t2imu {

std::vector<ActivityExample> activity_examples(const std::string& dir) {
    const CsvTable clips = read_csv(dir + "/clips.csv");
    const size_t id = clips.column("id"), tags = clips.column("activity_tags"), mirrored = clips.column("mirrored"),
                 subject = clips.column("subject"), source = clips.column("source_dataset");
    const size_t provenance = clips.has_column("provenance") ? clips.column("provenance") : SIZE_MAX;
    std::vector<ActivityExample> out;
    for (const auto& row : clips.rows) {
        const std::string& tag = row[tags];
        if (row[mirrored] != "0" || tag.empty() || tag == "other" || tag.find(';') != std::string::npos) continue;
        const std::string file = dir + "/new_joints/" + row[id] + ".npy";
        const JointSequence joints = joint_sequence_from_array(read_npy(file), file);
        if (joints.num_frames < 3) continue;
        // Subject names repeat across sources ("1" in two of them): qualify them by source, a derived clip's by
        // its source clip's, so that leaving a person out leaves out what was derived from them too.
        const bool derived = provenance < row.size() && !row[provenance].empty();
        const std::string dataset =
            derived ? nlohmann::json::parse(row[provenance]).value("source_dataset", row[source]) : row[source];
        out.push_back({tag, dataset + ":" + row[subject], describe_motion(joints)});
    }
    if (out.empty()) throw Error(dir + "/clips.csv", "activity_tags", "clips with one activity tag");
    return out;
}

}  // namespace t2imu
