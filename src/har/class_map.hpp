// Activity vocabularies differ between data sets: an explicit map per data set onto the evaluation's classes,
// and the rule that makes two data sets' classes comparable.
//
// Per data set (the manifest's `dataset` column); labels not listed keep their name:
//   sisfall  jogging -> running (SisFall's "jogging" trials are slow runs, D03/D04), stairs_up_down -> stairs
//            (up and down in one trial, not separable), jump_reach -> dropped (mostly standing with one to
//            three jumps: median |gyr| 0.10 rad/s, not the jumping class)
//   umafall  jogging -> running; "jumping" is UMAFall's Hopping, kept as jumping
//   t2imu    (synthetic; labels are the prompt set's, which may use a real data set's own names):
//            jogging -> running, stairs_up_down -> stairs, as for SisFall and UMAFall; nothing is dropped
//   hugadb, realworld: names are already canonical (RealWorld's climbingup/down were mapped to stairs_up/down
//            by its loader)
// Comparing two data sets: where one has `stairs` and the other `stairs_up`/`stairs_down`, both sides use
// `stairs`; then only the classes both sides have are kept (sorted by name).
#pragma once
#include <set>
#include <string>

namespace t2imu {

// The evaluation class of `activity` in `dataset`; "" when the activity is dropped.
std::string map_activity(const std::string& dataset, const std::string& activity);

// Merges fine classes into a coarse one when the other side only has the coarse one (see above).
std::string coarsen_for(const std::string& label, const std::set<std::string>& this_side, const std::set<std::string>& other_side);

}  // namespace t2imu
