// Reads a dataset in the HumanML3D layout (ours, or the official release exactly as laid out: new_joint_vecs/,
// texts/, Mean.npy, Std.npy, train.txt, val.txt, test.txt) and serves MDM's training batches, with the rules of
// MDM's Text2MotionDatasetV2:
// - a caption with start/end times makes a clip of its own from that span of the motion;
// - motions (and spans) shorter than 40 frames or of 200 frames and more are left out;
// - each draw crops a random window whose length is the motion's length rounded down to a multiple of 4 (one
//   time in three, 4 frames shorter still), takes one of the clip's captions at random, normalises with
//   Mean/Std and pads with zeros to 196 frames.
#pragma once
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "data/captions.hpp"
#include "motion/joint_sequence.hpp"
#include "motion/normalization.hpp"

namespace t2imu {

struct MotionClip {
    std::string id;          // the file id, with "#start-end" for a caption span
    FeatureMatrix features;  // [frames, 263], not normalised
    std::vector<CaptionLine> captions;
};

struct Batch {
    int size = 0;
    int frames = kMaxMotionFrames;  // padded length
    int channels = 263;
    std::vector<float> features;        // [size, frames, channels], normalised, zero after each length
    std::vector<uint8_t> mask;          // [size, frames], 1 on valid frames
    std::vector<int> lengths;           // [size]
    std::vector<std::string> captions;  // [size]
    std::vector<std::string> ids;       // [size]
};

class Hml3dDataset {
public:
    static constexpr int kMinFrames = 40;
    static constexpr int kMaxFramesExclusive = 200;
    static constexpr int kUnitLength = 4;
    // Whether a motion (or caption span) of `frames` frames at 20 fps is one the loader keeps.
    static bool usable_length(long frames) { return frames >= kMinFrames && frames < kMaxFramesExclusive; }

    // split: "train", "val", "test" or "all" (the ids of DIR/<split>.txt).
    Hml3dDataset(const std::string& dir, const std::string& split);

    const std::vector<MotionClip>& clips() const { return clips_; }
    const FeatureStats& stats() const { return stats_; }
    // Normalise batches with these statistics instead of DIR's Mean/Std (a fine-tuning keeps its base model's).
    void use_stats(const FeatureStats& stats) { stats_ = stats; }
    int skipped_ids() const { return skipped_; }  // listed ids with no usable motion or caption

    // The next batch of an endless sequence of seeded epochs: each epoch visits every clip once, shuffled.
    Batch next_batch(int batch_size);
    void seed(uint64_t seed);
    // The draw state (generator, epoch order, position) as text, so a resumed training continues the same
    // sequence of batches.
    std::string state() const;
    void restore_state(const std::string& state);

private:
    std::vector<MotionClip> clips_;
    FeatureStats stats_;
    int skipped_ = 0;
    std::mt19937_64 rng_{0};
    std::vector<size_t> order_;
    size_t cursor_ = 0;
};

}  // namespace t2imu
