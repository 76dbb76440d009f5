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
#include <string>
#include <vector>

#include "diffusion/mdm.hpp"
#include "diffusion/noise_schedule.hpp"
#include "diffusion/sample_options.hpp"
#include "diffusion/samplers.hpp"
#include "motion/joint_sequence.hpp"
#include "motion/normalization.hpp"
#include "text/nn/bert_encoder.hpp"
#include "text/nn/clip_text_encoder.hpp"
#include "text/nn/glove_text_encoder.hpp"

namespace t2imu {

struct MotionModel {
    std::unique_ptr<WordVectors> vocab;  // the text encoder keeps a reference: declared first, destroyed last
    Mdm mdm{nullptr};
    GloveTextEncoder text{nullptr};      // text_encoder.kind "glove_transformer" (t2imu train's models)
    ClipTextEncoder clip{nullptr};       // text_encoder.kind "clip" (official MDM checkpoints)
    BertEncoder minilm{nullptr};         // text_encoder.kind "minilm" (frozen sentence vectors)
    NoiseSchedule schedule;
    FeatureStats stats;
    nlohmann::json meta;  // model.json
    torch::Device device{torch::kCPU};

    torch::Tensor encode_text(const std::vector<std::string>& captions);  // [B, text_dim] by whichever encoder is loaded
    torch::nn::Module& text_module();                                     // that encoder
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
// `device` is cpu, cuda or cuda:N.
std::unique_ptr<MotionModel> load_motion_model(const std::string& dir, const std::string& device = "cpu");


// One de-normalised feature matrix [frames, 263] per prompt; validates `options` first.
std::vector<FeatureMatrix> sample_motions(MotionModel& model, const std::vector<std::string>& prompts, const SampleOptions& options);

}  // namespace t2imu
