// Training losses of MDM and of Häusler et al., on motions laid out as [batch, frames, channels] (our layout;
// the official code uses [batch, channels, 1, frames]), each term averaged over the valid frames of each
// sample (mask[b, f] = 1 for f < length[b]) and returned per sample [batch].
#pragma once
#include <torch/torch.h>

namespace t2imu {

// [batch, frames] float mask from lengths [batch] (int64).
torch::Tensor frame_mask(const torch::Tensor& lengths, int64_t frames);

// Official masked_l2: sum of squared errors over valid frames / (valid frames x channels + 1e-8). L_simple when
// applied to the predicted x0.
torch::Tensor masked_mse(const torch::Tensor& target, const torch::Tensor& prediction, const torch::Tensor& mask);

// Official velocity term: masked_mse of first differences over time, with the last channel left out as MDM
// does (its comment calls channel 262 "root location"; for HumanML3D it is a foot contact) and the mask of
// the later frame.
torch::Tensor velocity_mse(const torch::Tensor& target, const torch::Tensor& prediction, const torch::Tensor& mask);

// The paper's acceleration loss, L_acc = 1/(N-2) sum_{i=2}^{N-1} mean_c ((x[i+1] - 2x[i] + x[i-1]) - (x^[i+1] -
// 2x^[i] + x^[i-1]))_c^2 with N the sample's valid frames: the mean over the N-2 second differences whose three
// frames are valid and over the channels. The paper writes a squared norm over N-1; its reported figures (L_acc
// 0.056 on HumanML3D) are per channel, as a mean-reducing MSE gives, and only a per-channel mean keeps lambda_acc
// independent of the feature width (summed over 263 channels, lambda = 0.01 acted like 2.6).
torch::Tensor acceleration_loss(const torch::Tensor& target, const torch::Tensor& prediction,
                                const torch::Tensor& mask);

}  // namespace t2imu
