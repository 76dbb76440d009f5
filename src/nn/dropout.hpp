// hashed_dropout: dropout on the CPU at memory speed. libtorch 1.13's CPU dropout draws its mask with bernoulli_, one
// call of the generator per element, and MDM applies 17 dropouts per step, some to [256, 197, 197] attention maps: a
// third of a batch-64 step (bench/README.md, "Training step (issue 43)"). Here one 64-bit draw of libtorch's default
// CPU generator seeds a counter-based hash (splitmix64 of seed + element index), each 64-bit hash gives four
// 16-bit uniforms, and an element is kept when its uniform is at least p (p rounded to 1/65,536): faster,
// parallel over elements, and reproducible: the same generator state gives the same mask on any thread count,
// and a checkpoint that saves the generator resumes it. Kept elements are scaled by 1 / (1 - p), as
// torch::dropout does. On other devices, and with p = 0 or outside training, it is torch::dropout.
#pragma once
#include <torch/torch.h>

namespace t2imu {

torch::Tensor hashed_dropout(const torch::Tensor& x, double p, bool training);

// The keep mask alone (bool, x's shape) for a given seed: exposed for tests.
torch::Tensor dropout_keep_mask(at::IntArrayRef shape, double p, uint64_t seed);

}  // namespace t2imu
