#include "nn/dropout.hpp"

#include <ATen/CPUGeneratorImpl.h>
#include <ATen/Parallel.h>

#include "core/hash.hpp"

namespace t2imu {

namespace {

uint64_t draw_seed() {
    at::Generator generator = at::detail::getDefaultCPUGenerator();
    std::lock_guard<std::mutex> lock(generator.mutex());
    return generator.get<at::CPUGeneratorImpl>()->random64();
}

}  // namespace

torch::Tensor dropout_keep_mask(at::IntArrayRef shape, double p, uint64_t seed) {
    torch::Tensor keep = torch::empty(shape, torch::kBool);
    bool* out = keep.data_ptr<bool>();
    const int64_t n = keep.numel();
    const uint64_t threshold = static_cast<uint64_t>(p * 65536.0 + 0.5);
    at::parallel_for(0, (n + 3) / 4, 1 << 14, [&](int64_t begin, int64_t end) {
        for (int64_t i = begin; i < end; ++i) {
            const uint64_t z = splitmix64(seed + 0x9E3779B97F4A7C15ull * static_cast<uint64_t>(i + 1));
            for (int64_t k = 0; k < 4 && 4 * i + k < n; ++k) out[4 * i + k] = ((z >> (16 * k)) & 0xFFFF) >= threshold;
        }
    });
    return keep;
}

torch::Tensor hashed_dropout(const torch::Tensor& x, double p, bool training) {
    if (!training || p <= 0 || !x.device().is_cpu()) return torch::dropout(x, p, training);
    // One pass for the product (autograd keeps only the bool mask), one in place for the scale.
    return (x * dropout_keep_mask(x.sizes(), p, draw_seed())).mul_(1.0 / (1.0 - p));
}

}  // namespace t2imu
