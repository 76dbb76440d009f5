// A tiny text-to-motion training set and configuration for tests that need a trained model folder in seconds:
// six 60-frame clips cut from the example walk (two captions each) in the HumanML3D layout, and a six-word
// vocabulary.
#pragma once
#include <string>

namespace t2imu::test {

// Writes the dataset (new_joint_vecs/, texts/, train.txt, Mean.npy, Std.npy, vocab.safetensors) into `dir`.
std::string make_tiny_motion_dataset(const std::string& dir);
// A training configuration (MDM 2 x 32, T = 50, 40 steps) for `data`, writing the model to `out`; `extra` is
// appended (e.g. a [loss] table). Returns the .toml path, in `dir`.
std::string write_tiny_train_config(const std::string& dir, const std::string& data, const std::string& out,
                                    const std::string& extra = "");

}  // namespace t2imu::test
