#include "nn/state_dict.hpp"

#include <set>

#include "core/error.hpp"

namespace t2imu {

namespace {

std::vector<int64_t> sizes_of(const torch::Tensor& t) {
    return std::vector<int64_t>(t.sizes().begin(), t.sizes().end());
}

std::string shape_str(const std::vector<int64_t>& s) { return c10::str(c10::IntArrayRef(s)); }

// The shape each of `n` parts of a parameter of shape `want` must have in the file.
std::vector<int64_t> part_shape(std::vector<int64_t> want, size_t n, bool transposed) {
    if (transposed && want.size() == 2) std::swap(want[0], want[1]);
    if (n > 1 && !want.empty()) want[0] /= static_cast<int64_t>(n);
    return want;
}

}  // namespace

StateDictLayout prefixed_layout(const std::string& prefix, bool only_prefixed) {
    StateDictLayout layout;
    layout.source = [prefix](const std::string& name) { return TensorSource{{prefix + name}, false}; };
    if (only_prefixed)
        layout.foreign = [prefix](const std::string& key) { return key.compare(0, prefix.size(), prefix) != 0; };
    return layout;
}

torch::Tensor tensor_of(const NdArray& a) {
    std::vector<float> v = a.to<float>();
    return torch::from_blob(v.data(), a.shape, torch::kFloat).clone();
}

void load_state_dict(torch::nn::Module& module, const SafeTensors& weights, const std::string& path,
                     const StateDictLayout& layout) {
    std::set<std::string> used;
    torch::NoGradGuard no_grad;
    for (auto& p : module.named_parameters()) {
        const TensorSource source = layout.source ? layout.source(p.key()) : TensorSource{{p.key()}, false};
        const std::vector<int64_t> want = part_shape(sizes_of(p.value()), source.keys.size(), source.transposed);
        std::vector<torch::Tensor> parts;
        for (const std::string& key : source.keys) {
            const auto it = weights.tensors.find(key);
            if (it == weights.tensors.end()) throw Error(path, key, "a tensor of shape " + shape_str(want), "missing");
            if (it->second.shape != want) throw Error(path, key, "shape " + shape_str(want), it->second.shape_str());
            parts.push_back(tensor_of(it->second));
            used.insert(key);
        }
        torch::Tensor value = parts.size() == 1 ? parts[0] : torch::cat(parts, 0);
        if (source.transposed) value = value.t();
        p.value().copy_(value);
    }
    for (const auto& [key, a] : weights.tensors)
        if (!used.count(key) && !(layout.foreign && layout.foreign(key)))
            throw Error(path, key, layout.owner, "an unexpected tensor " + a.shape_str());
}

void load_state_dict(torch::nn::Module& module, const std::string& path, const StateDictLayout& layout) {
    load_state_dict(module, read_safetensors(path), path, layout);
}

void save_state_dict(const torch::nn::Module& module, const std::string& path) {
    SafeTensors st;
    for (const auto& p : module.named_parameters()) {
        const torch::Tensor v = p.value().detach().to(torch::kCPU, torch::kFloat32).contiguous();
        std::vector<float> data(v.data_ptr<float>(), v.data_ptr<float>() + v.numel());
        st.tensors[p.key()] = NdArray::from(data, sizes_of(v));
    }
    write_safetensors(path, st);
}

torch::nn::Module& holder_at(torch::nn::Module& root, const std::string& dotted_parent) {
    torch::nn::Module* m = &root;
    size_t start = 0;
    while (start <= dotted_parent.size()) {
        size_t dot = dotted_parent.find('.', start);
        if (dot == std::string::npos) dot = dotted_parent.size();
        const std::string name = dotted_parent.substr(start, dot - start);
        torch::nn::Module* next = nullptr;
        for (const auto& child : m->named_children())
            if (child.key() == name) next = child.value().get();
        m = next ? next : m->register_module(name, std::make_shared<torch::nn::Module>()).get();
        start = dot + 1;
    }
    return *m;
}

torch::Tensor register_parameter_at(torch::nn::Module& root, const std::string& path, torch::Tensor value) {
    const size_t dot = path.rfind('.');
    if (dot == std::string::npos) return root.register_parameter(path, value);
    return holder_at(root, path.substr(0, dot)).register_parameter(path.substr(dot + 1), value);
}

}  // namespace t2imu
