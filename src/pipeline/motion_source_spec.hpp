// Where a synthesis gets its motions, as typed values: --model's spelling parsed once at the door
// (pipeline/motion_source.hpp opens it). Torch-free, so a plan can hold it.
#pragma once
#include <string>
#include <variant>

namespace t2imu {

struct ModelFolderSpec {
    std::string folder;  // a trained text-to-motion model folder
};
struct RetrievalSpec {
    std::string dataset;  // a HumanML3D-layout dataset whose train split retrieval answers from
};
// The clip retrieval would give, noised to round(strength (T-1)) and finished by the model with the prompt (SDEdit;
// strength in (0, 1], 1 = the model alone from noise, small = the captured clip barely changed; draw records are
// retrieval's).
struct HybridSpec {
    std::string model_folder, dataset;
    double strength = 1;
};
using MotionSourceSpec = std::variant<ModelFolderSpec, RetrievalSpec, HybridSpec>;

// "MODEL_FOLDER", "retrieval:DATASET" or "hybrid:MODEL_FOLDER,DATASET,STRENGTH"; errors name --model.
MotionSourceSpec parse_motion_source(const std::string& spelling);

}  // namespace t2imu
