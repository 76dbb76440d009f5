// DeepConvLSTM (Ordóñez & Roggen 2016, Sensors 16(1):115) in libtorch, as published: four convolutions of 64
// filters with kernel 5 along time (each sensor channel convolved separately with shared filters, no padding,
// ReLU), two LSTM layers of 128 units, dropout 0.5, and a dense softmax layer on the last time step.
#pragma once
#include <torch/torch.h>

namespace t2imu {

// The shortest window (samples) the network takes: four unpadded convolutions of kernel 5 take 4 samples each.
constexpr int kDeepConvLstmMinWindow = 4 * (5 - 1) + 1;

struct DeepConvLstmImpl : torch::nn::Module {
    DeepConvLstmImpl(int channels, int classes, int filters = 64, int kernel = 5, int hidden = 128,
                     double dropout = 0.5);
    // x: [batch, time, channels] -> logits [batch, classes] (softmax is in the loss / argmax).
    torch::Tensor forward(const torch::Tensor& x);

    torch::nn::Conv2d conv1{nullptr}, conv2{nullptr}, conv3{nullptr}, conv4{nullptr};
    torch::nn::LSTM lstm{nullptr};
    torch::nn::Dropout dropout{nullptr};
    torch::nn::Linear dense{nullptr};
};
TORCH_MODULE(DeepConvLstm);

}  // namespace t2imu
