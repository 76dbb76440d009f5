// A model folder (model.json, weights.safetensors, Mean.npy, Std.npy and the text encoder's files) turned into
// motions for prompts: classifier-free guidance (one batched conditional and
// unconditional pass per step), any of the samplers (samplers.hpp), de-normalised HumanML3D features.
//
// Reproducibility: sample i of a call draws its x_T and every step's noise from its own generator seeded with
// seed + i, so a sample does not change with the other prompts of the call, nor with the batch size beyond
// float rounding (batched matrix products round differently); the same call gives the same bytes.
#pragma once
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "diffusion/mdm.hpp"
#include "diffusion/noise_schedule.hpp"
#include "diffusion/sample_options.hpp"
#include "diffusion/samplers.hpp"
#include "motion/joint_sequence.hpp"
#include "motion/normalization.hpp"
#include "text/caption_index.hpp"
#include "text/nn/bert_encoder.hpp"
#include "text/nn/clip_text_encoder.hpp"
#include "text/nn/glove_text_encoder.hpp"

namespace t2imu {

// The caption anchor: a prompt's text feature blended with the features of the training captions nearest it
// (caption_index.hpp: by SIF similarity, among the captions of the activity the prompt asks for), so that a
// prompt in words the text encoder did not learn still conditions the denoiser like the captions it did:
//   c = (1 - w) E(prompt) + w mean_j E(caption_j),   j over the K nearest captions of the prompt's activity
//   (all of the nearest one's own activity, so "stairs" blends one direction: caption_index.hpp),
// E the model's text encoder; w = 0 is the prompt alone, and so is a prompt whose activity is unknown or has no
// caption. The activity asked is the prompt set's label, else the one the prompt's words name (activity_asked).
// The unconditional pass of classifier-free guidance is unchanged (the zero feature). A model folder holds its
// training captions in captions.tsv (text/training_captions.hpp) and states K and its default w in model.json;
// t2imu train writes both, with the defaults below (models/default, K = 5, first draws showing their activity over
// seeds 0, 1000 and 2000, of 240: prompts/realworld.tsv 108 without the anchor, 184 at w = 0.75, 188 at w = 1;
// prompts/paraphrase.tsv 84, 170, 182).
constexpr size_t kCaptionAnchorNeighbours = 5;
constexpr double kCaptionAnchorWeight = 1.0;

struct CaptionAnchor {
    std::unique_ptr<CaptionIndex> index;  // null: the folder has no caption anchor
    size_t neighbours = 0;                // K
    double weight = 0;                    // the folder's default w
    bool match_attributes = false;        // rank captions by the prompt's attribute words first (caption_index.hpp)
};

struct MotionModel {
    std::unique_ptr<WordVectors> vocab;  // the text encoder keeps a reference: declared first, destroyed last
    Mdm mdm{nullptr};
    GloveTextEncoder text{nullptr};  // text_encoder.kind "glove_transformer" (t2imu train's models)
    ClipTextEncoder clip{nullptr};   // text_encoder.kind "clip" (official MDM checkpoints)
    BertEncoder minilm{nullptr};     // text_encoder.kind "minilm" (frozen sentence vectors)
    NoiseSchedule schedule;
    FeatureStats stats;
    nlohmann::json meta;  // model.json
    torch::Device device{torch::kCPU};
    CaptionAnchor anchor;  // searched with the GloVe vocabulary: glove_transformer models only

    torch::Tensor encode_text(
        const std::vector<std::string>& captions);  // [B, text_dim] by whichever encoder is loaded
    // The caption anchor's weight a run samples with: `asked` when given, else the folder's. Error naming
    // --caption-anchor for a weight above 0 on a folder without an anchor (callers ask before any output).
    double caption_anchor_weight(std::optional<double> asked) const;
    // The features [B, text_dim] the prompts condition the denoiser with: encode_text blended by the caption
    // anchor at weight w (checked as caption_anchor_weight does); activities: empty, or one canonical name per
    // prompt ("" = unknown).
    torch::Tensor condition(const std::vector<std::string>& prompts, const std::vector<std::string>& activities,
                            double weight);
    torch::nn::Module& text_module();  // that encoder
};

// model.json's text_encoder names the encoder:
//   {"kind": "glove_transformer", "vocab": PATH, sizes...}: weights in text_encoder.safetensors. The vocab path
//     is tried as written (absolute, or relative to the working directory), then relative to the model folder,
//     then as $T2IMU_VOCAB.
//   {"kind": "clip", "weights": PATH, "merges": PATH[, "text_tokens": 22]}: CLIP's frozen text tower
//     (clip_text_encoder.hpp; its sizes are read from the weights) and its BPE merges file (.txt.gz or .txt);
//     paths as written, then relative to the model folder. text_tokens is MDM's tokenizer context (22 for
//     HumanML3D and KIT, 77 for other data sets). The weights may be weights.safetensors itself, an MDM state
//     dict that kept its CLIP under clip_model.; otherwise a clip_model.* key there is refused like any other.
//   {"kind": "minilm", "weights": PATH, "vocab": PATH, "heads": 12[, "max_tokens": 256]}: a frozen BERT-family
//     sentence encoder (text/nn/bert_encoder.hpp; all-MiniLM-L6-v2's model.safetensors and vocab.txt, mean
//     pooled, unit length); sizes from the weights, the head count given; mdm.text_dim must equal its width
//     (384 for MiniLM). Paths as for clip.
// {"caption_anchor": {"captions": "captions.tsv", "neighbours": K, "weight": W[, "match_attributes": B]}} (optional,
// glove_transformer only): the caption anchor's captions (relative to the model folder), K of them blended at
// weight W by default; B (default false) ranks them by the prompt's attribute words first: for a model trained on
// measured captions (on models/default it cost SisFall HAR: docs/attributes.md, "The anchor and retrieval match
// the words").
// `device` is cpu, cuda or cuda:N.
std::unique_ptr<MotionModel> load_motion_model(const std::string& dir, const std::string& device = "cpu");

// One de-normalised feature matrix [frames, 263] per prompt; validates `options` first (and that activities, when
// given, are one per prompt).
std::vector<FeatureMatrix> sample_motions(MotionModel& model, const std::vector<std::string>& prompts,
                                          const SampleOptions& options);

}  // namespace t2imu
