#include "har/nn/deepconvlstm.hpp"

namespace t2imu {

namespace {
torch::nn::Conv2d temporal_conv(int in, int out, int kernel) {
    return torch::nn::Conv2d(torch::nn::Conv2dOptions(in, out, {kernel, 1}));  // along time only
}
}  // namespace

DeepConvLstmImpl::DeepConvLstmImpl(int channels, int classes, int filters, int kernel, int hidden, double p) {
    conv1 = register_module("conv1", temporal_conv(1, filters, kernel));
    conv2 = register_module("conv2", temporal_conv(filters, filters, kernel));
    conv3 = register_module("conv3", temporal_conv(filters, filters, kernel));
    conv4 = register_module("conv4", temporal_conv(filters, filters, kernel));
    // Dropout between the two LSTM layers is the LSTM's own; dropout before the first and after the last
    // is explicit, as in the paper's dropout on the recurrent layers' inputs and the dense layer's input.
    lstm = register_module(
        "lstm",
        torch::nn::LSTM(torch::nn::LSTMOptions(filters * channels, hidden).num_layers(2).batch_first(true).dropout(p)));
    dropout = register_module("dropout", torch::nn::Dropout(p));
    dense = register_module("dense", torch::nn::Linear(hidden, classes));
}

torch::Tensor DeepConvLstmImpl::forward(const torch::Tensor& x) {
    torch::Tensor h = x.unsqueeze(1);  // [B, 1, T, C]
    h = torch::relu(conv1->forward(h));
    h = torch::relu(conv2->forward(h));
    h = torch::relu(conv3->forward(h));
    h = torch::relu(conv4->forward(h));      // [B, F, T - 4 (k - 1), C]
    h = h.permute({0, 2, 1, 3}).flatten(2);  // [B, T', F * C]: every filter of every channel per step
    h = std::get<0>(lstm->forward(dropout->forward(h)));
    return dense->forward(dropout->forward(h.select(1, h.size(1) - 1)));
}

}  // namespace t2imu
