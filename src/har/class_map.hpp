// Activity vocabularies differ between data sets: an explicit map per data set onto the evaluation's classes,
// and the rule that makes two data sets' classes comparable.
//
// Per data set (the manifest's `dataset` column), its profile's class map (imu/dataset_profile.cpp: sisfall's
// jogging -> running, stairs_up_down -> stairs, jump_reach dropped; umafall's jogging -> running); labels not listed
// keep their name. t2imu (synthetic; labels are the prompt set's, which may use a real data set's own names):
// jogging -> running, stairs_up_down -> stairs; nothing is dropped.
// Comparing two data sets: where one has `stairs` and the other `stairs_up`/`stairs_down`, both sides use
// `stairs`; then only the classes both sides have are kept (sorted by name).
#pragma once
#include <set>
#include <string>

namespace t2imu {

// The evaluation class of `activity` in `dataset`; "" when the activity is dropped.
std::string map_activity(const std::string& dataset, const std::string& activity);

// Merges fine classes into a coarse one when the other side only has the coarse one (see above).
std::string coarsen_for(const std::string& label, const std::set<std::string>& this_side,
                        const std::set<std::string>& other_side);

}  // namespace t2imu
