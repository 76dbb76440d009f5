#include "data/activity_reference.hpp"

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "motion/joint_sequence.hpp"

namespace t2imu {

std::vector<ActivityExample> activity_examples(const std::string& dir) {
    const CsvTable clips = read_csv(dir + "/clips.csv");
    const size_t id = clips.column("id"), tags = clips.column("activity_tags"), mirrored = clips.column("mirrored"),
                 subject = clips.column("subject"), source = clips.column("source_dataset");
    std::vector<ActivityExample> out;
    for (const auto& row : clips.rows) {
        const std::string& tag = row[tags];
        if (row[mirrored] != "0" || tag.empty() || tag == "other" || tag.find(';') != std::string::npos) continue;
        const std::string file = dir + "/new_joints/" + row[id] + ".npy";
        const JointSequence joints = joint_sequence_from_array(read_npy(file), file);
        if (joints.num_frames < 3) continue;
        // Subject names repeat across sources ("1" in two of them): qualify them by source.
        out.push_back({tag, row[source] + ":" + row[subject], describe_motion(joints)});
    }
    if (out.empty()) throw Error(dir + "/clips.csv", "activity_tags", "clips with one activity tag");
    return out;
}

}  // namespace t2imu
