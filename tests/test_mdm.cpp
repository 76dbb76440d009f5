// The MDM denoiser against the official forward pass of a tiny model (shared/data/reference/mdm/forward).
#include <gtest/gtest.h>
#include <torch/torch.h>

#include "core/error.hpp"
#include "core/npy.hpp"
#include "core/safetensors.hpp"
#include "diffusion/mdm.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

torch::Tensor load_mdm_reference(const std::string& relative) {
    const NdArray a = read_npy(test::shared_path(relative));
    if (a.dtype == DType::i64) {
        std::vector<int64_t> v = a.to<int64_t>();
        return torch::from_blob(v.data(), a.shape, torch::kLong).clone();
    }
    std::vector<float> v = a.to<float>();
    return torch::from_blob(v.data(), a.shape, torch::kFloat).clone();
}

Mdm tiny_model() {
    Mdm model(read_mdm_config(test::shared_path("reference/mdm/mdm_tiny_config.json")));
    load_mdm_weights(model, test::shared_path("reference/mdm/mdm_tiny.safetensors"));
    model->eval();
    return model;
}

}  // namespace

TEST(Mdm, MatchesTheOfficialForwardCondUncondAndGuided) {
    std::string weights;
    SHARED_OR_SKIP(weights, "reference/mdm/mdm_tiny.safetensors");
    Mdm model = tiny_model();
    torch::NoGradGuard no_grad;
    const torch::Tensor x = load_mdm_reference("reference/mdm/forward/x.npy"),
                        t = load_mdm_reference("reference/mdm/forward/timesteps.npy");
    const torch::Tensor text = load_mdm_reference("reference/mdm/forward/text_embed.npy");
    const double cond = (model->forward(x, t, text) - load_mdm_reference("reference/mdm/forward/out_cond.npy"))
                            .abs()
                            .max()
                            .item<double>();
    const double uncond =
        (model->forward(x, t, text, true) - load_mdm_reference("reference/mdm/forward/out_uncond.npy"))
            .abs()
            .max()
            .item<double>();
    const double cfg =
        (model->forward_guided(x, t, text, 2.5) - load_mdm_reference("reference/mdm/forward/out_cfg_scale2.5.npy"))
            .abs()
            .max()
            .item<double>();
    EXPECT_LT(cond, 1e-5);
    EXPECT_LT(uncond, 1e-5);
    EXPECT_LT(cfg, 1e-5);
    std::printf("[ mdm      ] max abs difference: cond %.2e, uncond %.2e, guided 2.5 %.2e\n", cond, uncond, cfg);
}

TEST(Mdm, RefusesMissingUnexpectedAndMisShapedWeights) {
    std::string weights;
    SHARED_OR_SKIP(weights, "reference/mdm/mdm_tiny.safetensors");
    Mdm model(read_mdm_config(test::shared_path("reference/mdm/mdm_tiny_config.json")));
    const SafeTensors good = read_safetensors(weights);
    const std::string dir = test::scratch_dir("mdm_weights");
    auto expect_refused = [&](const SafeTensors& st, const std::string& key) {
        write_safetensors(dir + "/w.safetensors", st);
        try {
            load_mdm_weights(model, dir + "/w.safetensors");
            ADD_FAILURE() << "accepted a bad state dict for " << key;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
        }
    };
    SafeTensors missing = good;
    missing.tensors.erase("embed_text.weight");
    expect_refused(missing, "embed_text.weight");
    SafeTensors extra = good;
    extra.tensors["clip_model.proj"] = NdArray::from(std::vector<float>{1}, {1});
    expect_refused(extra, "clip_model.proj");
    SafeTensors shaped = good;
    shaped.tensors["output_process.poseFinal.bias"] = NdArray::from(std::vector<float>(262, 0.f), {262});
    expect_refused(shaped, "output_process.poseFinal.bias");
}

TEST(Mdm, MaskedFramesDoNotChangeValidOnes) {
    std::string weights;
    SHARED_OR_SKIP(weights, "reference/mdm/mdm_tiny.safetensors");
    MdmConfig config = read_mdm_config(test::shared_path("reference/mdm/mdm_tiny_config.json"));
    config.mask_frames = true;
    Mdm model(config);
    load_mdm_weights(model, weights);
    model->eval();
    torch::NoGradGuard no_grad;
    torch::manual_seed(5);
    torch::Tensor x = torch::randn({1, 263, 1, 10});
    const torch::Tensor t = torch::tensor({int64_t{300}}), text = torch::randn({1, 512}),
                        lengths = torch::tensor({int64_t{6}});
    const torch::Tensor a = model->forward(x, t, text, false, lengths);
    x.index_put_({0, torch::indexing::Slice(), 0, torch::indexing::Slice(6, 10)}, 100.0);  // change only padding
    const torch::Tensor b = model->forward(x, t, text, false, lengths);
    const auto valid = torch::indexing::Slice(0, 6);
    EXPECT_LT((a.index({0, "...", valid}) - b.index({0, "...", valid})).abs().max().item<float>(), 1e-5);
    // Without the mask the padding leaks into the valid frames.
    const torch::Tensor c = model->forward(x, t, text, false);
    EXPECT_GT((a.index({0, "...", valid}) - c.index({0, "...", valid})).abs().max().item<float>(), 1e-3);
}

// diffusion/mdm_io.cpp (what `t2imu model forward` runs): reads the arrays, checks their shapes, one pass.
TEST(Mdm, CliForwardMatchesTheReference) {
    std::string weights;
    SHARED_OR_SKIP(weights, "reference/mdm/mdm_tiny.safetensors");
    const std::string r = test::shared_path("reference/mdm");
    const std::string out = test::scratch_dir("mdm_cli") + "/out.npy";
    const auto run =
        test::run_cli("model forward --weights " + weights + " --config " + r + "/mdm_tiny_config.json --x " + r +
                      "/forward/x.npy --timesteps " + r + "/forward/timesteps.npy --text-embed " + r +
                      "/forward/text_embed.npy --guidance 2.5 --out " + out);
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_LT((load_mdm_reference("reference/mdm/forward/out_cfg_scale2.5.npy") -
               [&] {
                   const NdArray a = read_npy(out);
                   std::vector<float> v = a.to<float>();
                   return torch::from_blob(v.data(), a.shape, torch::kFloat).clone();
               }())
                  .abs()
                  .max()
                  .item<float>(),
              1e-5);
    const auto bad =
        test::run_cli("model forward --weights " + weights + " --config " + r + "/mdm_tiny_config.json --x " + r +
                      "/forward/text_embed.npy --timesteps " + r + "/forward/timesteps.npy --text-embed " + r +
                      "/forward/text_embed.npy --out " + out + "2");
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.output.find("text_embed.npy: shape"), std::string::npos) << bad.output;
}
