#include "nn/autocast.hpp"

#include <ATen/autocast_mode.h>
#include <torch/version.h>

#include "core/error.hpp"

namespace t2imu {

Precision parse_precision(const std::string& name, const std::string& file, const std::string& field) {
    if (name == "fp32") return Precision::kFloat32;
    if (name == "bf16") return Precision::kBFloat16;
    throw Error(file, field, "fp32 or bf16", name);
}

const char* precision_name(Precision p) { return p == Precision::kBFloat16 ? "bf16" : "fp32"; }

// libtorch 2.4 made autocast's state per device type (at::autocast::is_autocast_enabled(type), ...) and turned the
// per-backend functions 1.13 has (is_enabled for CUDA, is_cpu_enabled, ...) into wrappers that warn on every call.
// The 2.4+ branch is not compiled on this project's CI (Debian's libtorch 1.13).
#if TORCH_VERSION_MAJOR > 2 || (TORCH_VERSION_MAJOR == 2 && TORCH_VERSION_MINOR >= 4)
namespace {
at::DeviceType type_of(bool cuda) { return cuda ? at::kCUDA : at::kCPU; }
bool autocast_enabled(bool cuda) { return at::autocast::is_autocast_enabled(type_of(cuda)); }
at::ScalarType autocast_dtype(bool cuda) { return at::autocast::get_autocast_dtype(type_of(cuda)); }
void set_autocast(bool cuda, bool enabled, at::ScalarType dtype) {
    at::autocast::set_autocast_dtype(type_of(cuda), dtype);
    at::autocast::set_autocast_enabled(type_of(cuda), enabled);
}
}  // namespace
#else
namespace {
bool autocast_enabled(bool cuda) { return cuda ? at::autocast::is_enabled() : at::autocast::is_cpu_enabled(); }
at::ScalarType autocast_dtype(bool cuda) {
    return cuda ? at::autocast::get_autocast_gpu_dtype() : at::autocast::get_autocast_cpu_dtype();
}
void set_autocast(bool cuda, bool enabled, at::ScalarType dtype) {
    if (cuda) {
        at::autocast::set_autocast_gpu_dtype(dtype);
        at::autocast::set_enabled(enabled);
    } else {
        at::autocast::set_autocast_cpu_dtype(dtype);
        at::autocast::set_cpu_enabled(enabled);
    }
}
}  // namespace
#endif

AutocastScope::AutocastScope(const torch::Device& device, Precision precision) {
    if (precision == Precision::kFloat32) return;
    active_ = true;
    cuda_ = device.is_cuda();
    was_enabled_ = autocast_enabled(cuda_);
    previous_dtype_ = autocast_dtype(cuda_);
    set_autocast(cuda_, true, at::kBFloat16);
    at::autocast::increment_nesting();
}

AutocastScope::~AutocastScope() {
    if (!active_) return;
    // The outermost scope drops the cache of weights cast to bf16: they change at the next optimiser step.
    if (at::autocast::decrement_nesting() == 0) at::autocast::clear_cache();
    set_autocast(cuda_, was_enabled_, previous_dtype_);
}

}  // namespace t2imu
