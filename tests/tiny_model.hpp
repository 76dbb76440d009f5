// A tiny text-to-motion training set and configuration for tests that need a trained model folder in seconds:
// six 60-frame clips cut from the example walk (two captions each) in the HumanML3D layout, and a six-word
// vocabulary.
#pragma once
#include <string>
#include <vector>

namespace t2imu::test {

// Writes the dataset (new_joint_vecs/, texts/, train.txt, Mean.npy, Std.npy, vocab.safetensors) into `dir`.
std::string make_tiny_motion_dataset(const std::string& dir);
// Gives the clips `ids` of such a dataset capture-rate copies (dataset_builder.hpp's capture_joints/ and clips.csv
// columns) at 60 fps: each clip's 20 fps joints joined by Catmull-Rom curves, so a copy's every third frame is a
// frame of the clip. clips.csv is created (id, activity_tags walking, split) where the dataset has none.
void add_capture_copies(const std::string& dir, const std::vector<std::string>& ids);
// A training configuration (MDM 2 x 32, T = 50, 40 steps) for `data`, writing the model to `out`; `extra` is
// appended (e.g. a [loss] table). Returns the .toml path, in `dir`.
std::string write_tiny_train_config(const std::string& dir, const std::string& data, const std::string& out,
                                    const std::string& extra = "");

}  // namespace t2imu::test
