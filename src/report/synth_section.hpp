// The synthesis part of the report, for each folder `t2imu synth` wrote (synth_report.json beside jobs/*.json,
// motions/<job>_joints.npy and <job>.bvh, manifest.csv and recordings/):
//   - what was made per activity (kept, below the activity agreement, dropped, what the motions show) and the
//     run's time;
//   - every kept motion, grouped by activity: a strip of poses (report/pose_strip.hpp), the prompt, the quality
//     filter's outcome, the activity check's outcome and a link to the BVH relative to the report folder;
//   - signal statistics per activity at one position (report/signal_stats.hpp), a real data set's beside them
//     when given: a figure and a table of medians.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "imu/imu_dataset.hpp"
#include "imu/synth_folder.hpp"
#include "report/html_page.hpp"

namespace t2imu {

struct SynthFolder {
    std::string dir;     // the folder holding synth_report.json
    std::string title;   // its heading: "Synthesis: <title>"
    SynthReport report;  // its synth_report.json
};

// `real`: a real IMU data set (loaded), empty for none; `real_name` names it in the text.
void synth_section(const std::vector<SynthFolder>& folders, const std::vector<ImuRecording>& real,
                   const std::string& real_name, Page& page);

}  // namespace t2imu
