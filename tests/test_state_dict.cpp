// nn/state_dict.cpp: the one strict weight loader. Round trips by name, dotted reference names from nested
// registration, refusals naming the key (missing, mis-shaped, unexpected), foreign keys skipped, and a
// parameter assembled from several keys (fused q/k/v) and transposed (a Linear-stored projection).
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "nn/state_dict.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

// Two Linear layers at reference-style dotted paths and a free parameter: keys "proj",
// "encoder.layer.0.dense.weight", "encoder.layer.0.dense.bias", "head.weight", "head.bias".
struct Small : torch::nn::Module {
    torch::nn::Linear dense{nullptr}, head{nullptr};
    torch::Tensor proj;
    Small() {
        dense = register_module_at(*this, "encoder.layer.0.dense", torch::nn::Linear(3, 4));
        head = register_module("head", torch::nn::Linear(4, 2));
        proj = register_parameter_at(*this, "proj", torch::randn({4, 6}));
    }
};

NdArray array_of(const torch::Tensor& t) {
    const torch::Tensor c = t.detach().contiguous();
    return NdArray::from(std::vector<float>(c.data_ptr<float>(), c.data_ptr<float>() + c.numel()),
                         std::vector<int64_t>(c.sizes().begin(), c.sizes().end()));
}

bool same_parameters(torch::nn::Module& a, torch::nn::Module& b) {
    const auto pa = a.named_parameters(), pb = b.named_parameters();
    for (const auto& p : pa)
        if (!torch::equal(p.value(), pb[p.key()])) return false;
    return pa.size() == pb.size();
}

}  // namespace

TEST(StateDict, NestedRegistrationGivesDottedReferenceNames) {
    Small m;
    std::vector<std::string> names;
    for (const auto& p : m.named_parameters()) names.push_back(p.key());
    // A module's own parameters come before its children's (libtorch's order, as PyTorch's state_dict).
    EXPECT_EQ(names, (std::vector<std::string>{"proj", "encoder.layer.0.dense.weight", "encoder.layer.0.dense.bias",
                                               "head.weight", "head.bias"}));
}

TEST(StateDict, SaveThenLoadGivesTheSameParametersBitForBit) {
    torch::manual_seed(1);
    Small a;
    torch::manual_seed(2);
    Small b;
    ASSERT_FALSE(same_parameters(a, b));
    const std::string path = test::scratch_dir("state_dict") + "/round.safetensors";
    save_state_dict(a, path);
    load_state_dict(b, path);
    EXPECT_TRUE(same_parameters(a, b));
}

TEST(StateDict, RefusesMissingMisshapedAndUnexpectedKeysByName) {
    Small m;
    const std::string dir = test::scratch_dir("state_dict");
    SafeTensors full;
    for (const auto& p : m.named_parameters()) full.tensors[p.key()] = array_of(p.value());

    SafeTensors missing = full;
    missing.tensors.erase("head.bias");
    std::string msg = test::error_message([&] { load_state_dict(m, missing, dir + "/x.safetensors"); });
    EXPECT_NE(msg.find("head.bias"), std::string::npos) << msg;
    EXPECT_NE(msg.find("missing"), std::string::npos) << msg;

    SafeTensors shape = full;
    shape.tensors["proj"] = NdArray::from(std::vector<float>(24, 0.f), {6, 4});
    msg = test::error_message([&] { load_state_dict(m, shape, dir + "/x.safetensors"); });
    EXPECT_NE(msg.find("proj"), std::string::npos) << msg;
    EXPECT_NE(msg.find("[4, 6]"), std::string::npos) << msg;
    EXPECT_NE(msg.find("(6, 4)"), std::string::npos) << msg;

    SafeTensors extra = full;
    extra.tensors["pooler.weight"] = NdArray::from(std::vector<float>(4, 0.f), {4});
    msg = test::error_message([&] { load_state_dict(m, extra, dir + "/x.safetensors"); });
    EXPECT_NE(msg.find("pooler.weight"), std::string::npos) << msg;
    EXPECT_NE(msg.find("unexpected"), std::string::npos) << msg;

    StateDictLayout skip;
    skip.foreign = [](const std::string& key) { return key.rfind("pooler.", 0) == 0; };
    EXPECT_NO_THROW(load_state_dict(m, extra, dir + "/x.safetensors", skip));
}

TEST(StateDict, PrefixedLayoutReadsOnePartOfALargerFile) {
    torch::manual_seed(3);
    Small a;
    Small b;
    SafeTensors st;
    for (const auto& p : a.named_parameters()) st.tensors["model." + p.key()] = array_of(p.value());
    st.tensors["other.thing"] = NdArray::from(std::vector<float>(2, 1.f), {2});
    EXPECT_NE(test::error_message([&] { load_state_dict(b, st, "f", prefixed_layout("model.")); }).find("other.thing"),
              std::string::npos);
    load_state_dict(b, st, "f", prefixed_layout("model.", true));
    EXPECT_TRUE(same_parameters(a, b));
}

TEST(StateDict, AssemblesAParameterFromThirdsAndATransposedMatrix) {
    Small m;
    // "proj" [4, 6] stored as three [2, 4] parts of its transpose [6, 4]: rows 0-1, 2-3 and 4-5.
    const torch::Tensor want = torch::arange(24, torch::kFloat).reshape({4, 6});
    const torch::Tensor t = want.t().contiguous();
    SafeTensors st;
    for (const auto& p : m.named_parameters())
        if (p.key() != "proj") st.tensors[p.key()] = array_of(p.value());
    for (int i = 0; i < 3; ++i) st.tensors["proj." + std::to_string(i)] = array_of(t.narrow(0, 2 * i, 2));
    StateDictLayout layout;
    layout.source = [](const std::string& name) {
        return name == "proj" ? TensorSource{{"proj.0", "proj.1", "proj.2"}, true} : TensorSource{{name}, false};
    };
    load_state_dict(m, st, "f", layout);
    EXPECT_TRUE(torch::equal(m.proj, want));
}
