// The captions a model was trained on, each with the activity of the clip it describes: what a model folder's
// captions.tsv holds for the caption anchor (diffusion/text_to_motion.hpp), written as a prompt set
// (activity<TAB>caption, prompt_set.hpp) so that it reads back with read_prompt_set.
//
// The activity of a caption: each activity tag of its clip in the dataset's clips.csv (data/clip_activities.hpp;
// a caption of a clip with two tags is listed under both; "other" stays "other"); for a clip clips.csv does not
// tag (the official HumanML3D has no clips.csv), the activity its words name (activity_named_in), else "other".
#pragma once
#include <string>
#include <vector>

#include "data/hml3d_dataset.hpp"
#include "text/prompt_set.hpp"

namespace t2imu {

// Every caption of every clip of `data` (read from `dataset_dir`, whose clips.csv gives the tags), each
// (activity, caption) pair once, in clip order.
std::vector<Prompt> training_captions(const Hml3dDataset& data, const std::string& dataset_dir);

// Written atomically: a comment line naming the format, then one `activity<TAB>caption` line per caption.
void write_training_captions(const std::string& path, const std::vector<Prompt>& captions);

}  // namespace t2imu
