// Prompt sets (prompts/*.tsv): one prompt per line, or `activity<TAB>prompt` where activity is the class name
// the synthetic recordings are labelled with (the IMU dataset layout's canonical names, or a real data set's
// own). Lines starting with # and empty lines are skipped; a trailing CR is dropped.
#pragma once
#include <string>
#include <vector>

namespace t2imu {

struct Prompt {
    std::string activity;  // "" when the line has no tab
    std::string text;
};

// Refuses an unreadable or empty file, naming it.
std::vector<Prompt> read_prompt_set(const std::string& path);

}  // namespace t2imu
