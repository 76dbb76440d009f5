#include "nn/autocast.hpp"

#include <ATen/autocast_mode.h>

#include "core/error.hpp"

namespace t2imu {

Precision parse_precision(const std::string& name, const std::string& file, const std::string& field) {
    if (name == "fp32") return Precision::kFloat32;
    if (name == "bf16") return Precision::kBFloat16;
    throw Error(file, field, "fp32 or bf16", name);
}

const char* precision_name(Precision p) { return p == Precision::kBFloat16 ? "bf16" : "fp32"; }

AutocastScope::AutocastScope(const torch::Device& device, Precision precision) {
    if (precision == Precision::kFloat32) return;
    active_ = true;
    cuda_ = device.is_cuda();
    if (cuda_) {
        was_enabled_ = at::autocast::is_enabled();
        previous_dtype_ = at::autocast::get_autocast_gpu_dtype();
        at::autocast::set_autocast_gpu_dtype(at::kBFloat16);
        at::autocast::set_enabled(true);
    } else {
        was_enabled_ = at::autocast::is_cpu_enabled();
        previous_dtype_ = at::autocast::get_autocast_cpu_dtype();
        at::autocast::set_autocast_cpu_dtype(at::kBFloat16);
        at::autocast::set_cpu_enabled(true);
    }
    at::autocast::increment_nesting();
}

AutocastScope::~AutocastScope() {
    if (!active_) return;
    // The outermost scope drops the cache of weights cast to bf16: they change at the next optimiser step.
    if (at::autocast::decrement_nesting() == 0) at::autocast::clear_cache();
    if (cuda_) {
        at::autocast::set_enabled(was_enabled_);
        at::autocast::set_autocast_gpu_dtype(previous_dtype_);
    } else {
        at::autocast::set_cpu_enabled(was_enabled_);
        at::autocast::set_autocast_cpu_dtype(previous_dtype_);
    }
}

}  // namespace t2imu
