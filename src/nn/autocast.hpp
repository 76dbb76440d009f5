// Mixed precision for a scope of libtorch calls: while an AutocastScope lives, matrix products, convolutions and
// attention on its device run in bfloat16 (8-bit mantissa, float32's range), while reductions, norms, softmax
// and the losses stay in float32 (libtorch's autocast lists). The weights stay float32 (the master copy the
// optimiser updates); only the products' inputs are rounded. Why: on a CPU with AVX-512 BF16 (oneDNN) a bf16
// product runs several times faster than Debian's OpenBLAS float32 one (bench/README.md, "Training step (issue
// 43)"), and GPUs have had bf16 tensor cores since Ampere.
#pragma once
#include <string>

#include <torch/torch.h>

namespace t2imu {

// "fp32" (no autocast) or "bf16". Throws Error naming `file` and `field` for anything else.
enum class Precision { kFloat32, kBFloat16 };
Precision parse_precision(const std::string& name, const std::string& file, const std::string& field);
const char* precision_name(Precision p);

class AutocastScope {
public:
    // A no-op for kFloat32. Otherwise enables autocast to bfloat16 for `device`'s type (CPU or CUDA) until
    // destroyed; nests, and restores the enclosing state.
    AutocastScope(const torch::Device& device, Precision precision);
    ~AutocastScope();
    AutocastScope(const AutocastScope&) = delete;
    AutocastScope& operator=(const AutocastScope&) = delete;

private:
    bool active_ = false, cuda_ = false, was_enabled_ = false;
    at::ScalarType previous_dtype_ = at::kFloat;
};

}  // namespace t2imu
