// Builds a training set in the HumanML3D layout from motion capture and captions:
//   new_joints/ID.npy      [F,22,3] float32, recover_from_ric(features), as HumanML3D stores them
//   new_joint_vecs/ID.npy  [F,263] float32 features (process_file)
//   texts/ID.txt           caption#tokens#start#end lines
//   Mean.npy, Std.npy      over every clip, mirrored ones included (as cal_mean_variance does)
//   train.txt, val.txt, test.txt, all.txt   ids; a clip and its mirror share a split
//   capture_joints/ID.npy  [G,22,3] float32: a captured clip at its capture rate where that is over 20 fps (120 fps
//                          HDM05 kept at 60, Bandai Namco 30, ReActIdle 24; mocap_import.hpp's capture_fps_for),
//                          placed as new_joints (place_like_process_file), from the captured frame at or before the
//                          clip's first: what the virtual sensors see of a retrieved clip (motion_source.hpp). A clip
//                          derived from such a recording is made at its rate and has its copy too.
//   clips.csv              id, file, source_dataset, subject, licence, activity_tags, start/end frame, frames,
//   mirrored,
//                          provenance (JSON of a derived clip: source file, method, parameters, seed; empty if
//                          captured), capture_fps and capture_start_s (the copy's rate and its first frame's time after
//                          the clip's first, s, in (-1/capture_fps, 0]; empty without a copy), split
//   captions.csv           id, caption, source: every caption line of texts/, from the captured clip's captions
//   ("human"), a
//                          derived clip's edit ("edited") or its measured motion ("measured", measured_captions.hpp)
//   summary.json           clips, minutes, captions, per activity tag (captured and derived minutes), each tag's share
//                          of the training draws, derived clips refused or failing quality, skipped files and why
//
// Inputs: `mocap_dir` with the motion files at the paths the captions CSV names (columns
// file,start_frame,end_frame,caption; optional tokens, licence, subject, source; frames at 20 fps, end exclusive),
// and optionally a manifest.csv (file, subject, source_dataset, licence, activity_tags) as the shared set has.
// Clips longer than max_seconds are cut into equal consecutive chunks no longer than that (HumanML3D's clips
// are at most 10 s), of which at most max_seconds_per_file worth are kept; a whole-clip caption goes with every chunk,
// a segment caption with the chunks it overlaps by at least 2 s, its times made relative to the chunk. The set is built
// in a temporary folder and renamed into place when complete.
#pragma once
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "core/csv.hpp"
#include "data/derived_clips.hpp"

namespace t2imu {

struct BuildOptions {
    std::string mocap_dir;
    std::string captions_csv;  // "" = mocap_dir/captions.csv
    std::string out_dir;
    bool mirror = false;
    // Licence families to keep ("" = all): CMU, HDM05, BandaiNamco (the clip's source_dataset), and KIT-ML for
    // the KIT-ML captions (their licence is unverified).
    std::set<std::string> licences;
    double max_seconds = 9.8;
    // At most this much of one file (0 = all of it), as chunks spread evenly over it: ReActIdle's 22 recordings
    // of standing idle run 92-162 s (46.7 min, more than all our walking), every other file of the shared set
    // is under 64 s. Uncapped, standing would be a quarter of the training draws (the loader visits every clip
    // once an epoch); at 60 s it keeps 6 chunks of each idle recording (21.6 min).
    double max_seconds_per_file = 60;
    // Add the clips derived from captured ones (derived_clips.hpp: stairs from walks, sitting down and standing
    // up from idle standing), tagged source_dataset "edited" with their provenance in clips.csv.
    bool derive = true;
    // Among them, the kinds that are off by default (derived_clips.hpp, DeriveOptions: what and why).
    DeriveOptions derived_kinds;
    // Keep each captured clip at its capture rate too (capture_joints/), and derive clips from the recording at
    // that rate (their copy is the derived clip at it; new_joints hold it at 20 fps, Catmull-Rom). false: every
    // clip, derived ones too, only at 20 fps.
    bool capture_rate = true;
    // Captions measured from each clip's motion (data/measured_captions.hpp), at most this many per clip, beside
    // the human ones (0 = none); captions.csv tags each caption line with its source.
    int measured_captions = 0;
    bool strict = false;  // abort on the first clip that fails to import (default: skip it and report it)

    // Throws Error naming the option unless the folders are given and the lengths are in range.
    void validate() const;
};

struct BuildSummary {
    int clips = 0;  // written, mirrored ones included
    int captions = 0;
    double minutes = 0;
    int skipped_files = 0;
    std::string json;  // the summary.json text
};

BuildSummary build_dataset(const BuildOptions& options);

// Per activity tag set of clips.csv ("walking", "jumping;standing", ...), the share of the training loader's draws
// (summary.json's train_draw_share): it visits every train-split clip of a usable length once an epoch
// (hml3d_dataset.hpp; a 0.65 s hop is never drawn), so the share of those clips.
nlohmann::json train_draw_share(const CsvTable& clips);

}  // namespace t2imu
