// Module parameters <-> safetensors, by name, strictly: the one loader of weights for every model here (MDM, the
// GloVe, CLIP and BERT text encoders). A state dict is the flat map from a parameter's dotted libtorch name
// ("seqTransEncoder.layers.0.linear1.weight") to a tensor; files keep the key names of the reference
// implementation a module mirrors, so weights move between this project and PyTorch by name.
//
// Strict means: every parameter of the module must be found with its exact shape, and every key of the file
// must be used, unless the layout declares it foreign (a full CLIP checkpoint's vision tower, an MDM state dict
// that keeps its CLIP, BERT's pooler). Each refusal is one Error naming the file, the key and both shapes.
// Values are read as float32 whatever the file's dtype (F16, BF16 and F64 convert). Buffers are not part of
// the files: the modules here compute theirs (positional tables) from their configuration.
#pragma once
#include <torch/torch.h>

#include <functional>
#include <string>
#include <vector>

#include "core/safetensors.hpp"

namespace t2imu {

// Where one parameter lies in a file: a single key, or several concatenated along dim 0 (Hugging Face keeps
// the q, k and v parts of a fused in-projection apart), the result optionally transposed (a projection stored
// as a Linear weight, P^T).
struct TensorSource {
    std::vector<std::string> keys;
    bool transposed = false;
};

struct StateDictLayout {
    std::function<TensorSource(const std::string& name)> source;  // empty: the parameter's own name
    std::function<bool(const std::string& key)> foreign;          // keys that are not this module's; empty: none
    std::string owner = "a parameter of the model";               // what an unexpected key would have to be
};

// The layout of a file whose keys are the parameters' names behind `prefix` ("" = as they are); keys that do
// not start with the prefix are foreign when `only_prefixed`, unexpected otherwise.
StateDictLayout prefixed_layout(const std::string& prefix, bool only_prefixed = false);

void load_state_dict(torch::nn::Module& module, const SafeTensors& weights, const std::string& path,
                     const StateDictLayout& layout = {});
void load_state_dict(torch::nn::Module& module, const std::string& safetensors_path,
                     const StateDictLayout& layout = {});

// Every parameter under its own name, float32, contiguous, through a temporary file (atomic).
void save_state_dict(const torch::nn::Module& module, const std::string& safetensors_path);

// A float32 CPU tensor holding a copy of `a`'s values, in its shape.
torch::Tensor tensor_of(const NdArray& a);

// libtorch names submodules without dots; reference implementations nest them ("encoder.layer.0.attention").
// These register `module` (or a parameter) at a dotted path below `root`, creating empty holder modules on the
// way, so that named_parameters() gives the reference's key names.
torch::nn::Module& holder_at(torch::nn::Module& root, const std::string& dotted_parent);
template <class M>
M register_module_at(torch::nn::Module& root, const std::string& path, M module) {
    const size_t dot = path.rfind('.');
    if (dot == std::string::npos) return root.register_module(path, module);
    return holder_at(root, path.substr(0, dot)).register_module(path.substr(dot + 1), module);
}
torch::Tensor register_parameter_at(torch::nn::Module& root, const std::string& path, torch::Tensor value);

}  // namespace t2imu
