#include "diffusion/mdm_io.hpp"

#include "core/error.hpp"
#include "core/npy.hpp"
#include "diffusion/mdm.hpp"

namespace t2imu {

namespace {

torch::Tensor float_tensor(const std::string& path) {
    const NdArray a = read_npy(path);
    std::vector<float> v = a.to<float>();
    return torch::from_blob(v.data(), a.shape, torch::kFloat).clone();
}

torch::Tensor long_tensor(const std::string& path) {
    const NdArray a = read_npy(path);
    std::vector<int64_t> v = a.to<int64_t>();
    return torch::from_blob(v.data(), a.shape, torch::kLong).clone();
}

}  // namespace

void run_mdm_forward(const MdmForwardFiles& f) {
    Mdm model(read_mdm_config(f.config));
    load_mdm_weights(model, f.weights);
    model->eval();
    torch::NoGradGuard no_grad;
    const torch::Tensor x = float_tensor(f.x), t = long_tensor(f.timesteps), text = float_tensor(f.text);
    const int64_t njoints = model->config().njoints;
    if (x.dim() != 4 || x.size(1) != njoints || x.size(2) != 1)
        throw Error(f.x, "shape", "[batch, " + std::to_string(njoints) + ", 1, frames]", c10::str(x.sizes()));
    if (t.dim() != 1 || t.size(0) != x.size(0))
        throw Error(f.timesteps, "shape", "[" + std::to_string(x.size(0)) + "]", c10::str(t.sizes()));
    if (text.dim() != 2 || text.size(0) != x.size(0) || text.size(1) != model->config().text_dim)
        throw Error(f.text, "shape",
                    "[" + std::to_string(x.size(0)) + ", " + std::to_string(model->config().text_dim) + "]",
                    c10::str(text.sizes()));
    if (x.size(3) + 1 > model->config().max_len) throw Error(f.x, "frames", "fewer than the positional table's length");
    const torch::Tensor lengths = f.lengths.empty() ? torch::Tensor() : long_tensor(f.lengths);
    const torch::Tensor out = f.guidance != 0 ? model->forward_guided(x, t, text, f.guidance, lengths)
                                              : model->forward(x, t, text, f.uncond, lengths);
    const torch::Tensor c = out.contiguous();
    std::vector<float> v(c.data_ptr<float>(), c.data_ptr<float>() + c.numel());
    write_npy(f.out, NdArray::from(v, std::vector<int64_t>(c.sizes().begin(), c.sizes().end())));
}

}  // namespace t2imu
