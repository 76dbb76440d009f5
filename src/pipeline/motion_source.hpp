// Where a synthesis gets its motions: a trained text-to-motion model folder (diffusion sampling), the
// retrieval baseline `retrieval:DATASET` that answers a prompt with captured training clips, or the hybrid of
// the two (a retrieved clip, partly noised, finished by the model).
//
// A model asked (SampleOptions::stairs_round_trips) for a prompt whose activity is stairs both ways ("up the
// stairs and back down": SisFall's D05/D06) draws it in two halves, an ascent anchored to the stairs_up captions
// and a descent to the stairs_down ones, joined at a stance of one foot (gait_splice.hpp): the model learned each
// direction from clips of one (its anchor blends one direction) and never the pair. draw_record says whether the
// halves joined and where.
//
// Retrieval (the row that shows what the learned models add; the paper compares with ReMoDiffuse, a
// retrieval-augmented diffusion model) answers with clips of DATASET's train split (HumanML3D layout, t2imu data
// build or the official release) that show the prompt's activity. The activity asked is the prompt set's label
// (activity_names.hpp's canonical name: SisFall's "jogging" asks for running), else the one the prompt's words
// name ("sprints" -> running, "goes upstairs" -> stairs_up). Candidates come in tiers, the first non-empty one
// used: clips whose activity tags (DATASET/clips.csv) name the activity and whose motion the activity classifier
// places in that activity (when a classifier is given and has a class for the activity); clips whose tags name it;
// every clip (no activity asked or none tagged). Within the tier each clip scores by its best caption: the SIF
// similarity (GloVe, a = 1e-4, as the activity categoriser), and over a build with measured captions first the most of
// the prompt's attributes it names (slowly, left, then: data/measured_captions.hpp); a sample takes one of the
// kRetrievalTopK best at random (with every clip tied with the k-th: derived clips share their captions, hundreds to a
// sentence, and a tie broken by clip order drew every stairs motion from the first-listed recordings' acted walks),
// time-warps it by a factor in [1 - kRetrievalWarp, 1 + kRetrievalWarp] (the dataset holds the left-right mirrors
// already) and crops a random window of the asked length (a shorter clip is used whole). Nothing is invented: every
// frame is captured (or, for clips.csv's source_dataset "edited", derived) motion, resampled. A clip with a
// capture-rate copy (captured, or derived from a capture at that rate) gives that copy's same span too
// (capture_rate_motion; Catmull-Rom between its frames), so the virtual sensors can see the motion between 20 fps
// frames.
#pragma once
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "diffusion/text_to_motion.hpp"
#include "motion/joint_sequence.hpp"
#include "pipeline/motion_source_spec.hpp"

namespace t2imu {

constexpr int kRetrievalTopK = 5;
// Its halves' stances are found on joints smoothed over one frame at 20 fps (GaitSpliceOptions): a model's feet
// flicker where they stand.
constexpr double kRoundTripContactSmoothingS = 0.05;
constexpr double kRetrievalWarp = 0.1;

class MotionSource {
public:
    virtual ~MotionSource() = default;
    // One motion per prompt: SMPL-22 joints (m, Y up, floor at y = 0) at 20 fps, `frames` long (retrieval: at
    // most). Prompt i draws only from seeds[i], so a motion does not depend on the other prompts of the call.
    // activities[i]: the prompt set's label of prompt i ("" = unknown): the activity retrieval asks for, and the one
    // whose captions a model's caption anchor blends in (text_to_motion.hpp).
    virtual std::vector<JointSequence> generate(const std::vector<std::string>& prompts,
                                                const std::vector<std::string>& activities,
                                                const std::vector<uint64_t>& seeds, int frames) = 0;
    // What produced the motions, for the synthesis record (model folder, training step, sampler...).
    virtual nlohmann::json describe() const = 0;
    // What produced motion i of the last generate() call (retrieval: the clip, its tags, the tier), or null.
    virtual nlohmann::json draw_record(size_t) const { return nullptr; }
    // Motion i of the last generate() call at its capture rate, the same span of the same captured motion (at most
    // a capture frame's interpolation apart at the ends), or nothing: retrieval of a captured clip from a dataset
    // that holds capture-rate copies (dataset_builder.hpp) has one; derived clips and the models' motions do not.
    // Placed like the 20 fps motion up to a turn about the vertical and a shift, which no body-frame sensor reads.
    virtual std::optional<JointSequence> capture_rate_motion(size_t) const { return std::nullopt; }
    // The captions the source draws from, by activity: what a prompt's coverage is judged against
    // (text/prompt_coverage.hpp): a model's caption anchor, retrieval's clips. Null when it has none.
    virtual const CaptionIndex* caption_index() const { return nullptr; }
};

// `sampling` holds the sampler settings of a model (its seed fields are ignored: generate() takes the seeds). `vocab`:
// the GloVe vocabulary for retrieval ("" = the default: $T2IMU_VOCAB, else cache/text/glove-100k.safetensors).
// `activity_reference`: the motion activity classifier's reference CSV that retrieval checks candidates with ("" =
// activity tags alone).
std::unique_ptr<MotionSource> open_motion_source(const MotionSourceSpec& spec, const SampleOptions& sampling,
                                                 const std::string& device, const std::string& vocab = "",
                                                 const std::string& activity_reference = "");

}  // namespace t2imu
