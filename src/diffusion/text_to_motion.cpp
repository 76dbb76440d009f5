#include "diffusion/text_to_motion.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "diffusion/samplers.hpp"
#include "nn/state_dict.hpp"

namespace t2imu {

namespace {

std::string find_vocab(const std::string& dir, const std::string& written) {
    namespace fs = std::filesystem;
    if (fs::exists(written)) return written;
    if (fs::exists(fs::path(dir) / written)) return (fs::path(dir) / written).string();
    if (const char* env = std::getenv("T2IMU_VOCAB"); env && fs::exists(env)) return env;
    throw Error(dir + "/model.json", "text_encoder.vocab",
                "the GloVe vocabulary (scripts/setup.sh makes cache/text/glove-100k.safetensors; run from the "
                "repository root or set T2IMU_VOCAB)",
                written);
}

std::string find_encoder_file(const std::string& dir, const nlohmann::json& t, const char* field, const char* what) {
    namespace fs = std::filesystem;
    const std::string written = t.at(field).get<std::string>();
    if (fs::exists(written)) return written;
    if (fs::exists(fs::path(dir) / written)) return (fs::path(dir) / written).string();
    throw Error(dir + "/model.json", std::string("text_encoder.") + field,
                std::string("an existing file: ") + what + " (as written or relative to the model folder)", written);
}

// A whole number in [lo, hi] from model.json; the error names the field and the range. Bounds are what a model
// can have (a negative size would otherwise surface as a shape mismatch blamed on the weights).
int64_t model_integer(const nlohmann::json& parent, const std::string& file, const std::string& section,
                      const char* key, int64_t lo, int64_t hi) {
    const std::string expected = "an integer from " + std::to_string(lo) + " to " + std::to_string(hi);
    if (!parent.contains(key)) throw Error(file, section + "." + key, expected, "missing");
    const nlohmann::json& v = parent.at(key);
    if (!v.is_number_integer() || v.get<int64_t>() < lo || v.get<int64_t>() > hi)
        throw Error(file, section + "." + key, expected, v.dump());
    return v.get<int64_t>();
}

constexpr int64_t kMaxWidth = 1 << 16, kMaxLayers = 256;

MdmConfig mdm_config(const nlohmann::json& m, const std::string& file) {
    MdmConfig mc;
    mc.latent_dim = model_integer(m, file, "mdm", "latent_dim", 1, kMaxWidth);
    mc.ff_size = model_integer(m, file, "mdm", "ff_size", 1, kMaxWidth);
    mc.num_layers = model_integer(m, file, "mdm", "num_layers", 1, kMaxLayers);
    mc.num_heads = model_integer(m, file, "mdm", "num_heads", 1, mc.latent_dim);
    if (mc.latent_dim % mc.num_heads != 0)
        throw Error(file, "mdm.num_heads", "a divisor of mdm.latent_dim", std::to_string(mc.num_heads));
    const nlohmann::json& dropout = m.at("dropout");
    if (!dropout.is_number() || !(dropout.get<double>() >= 0 && dropout.get<double>() < 1))
        throw Error(file, "mdm.dropout", "a number from 0 to below 1", dropout.dump());
    mc.dropout = dropout.get<double>();
    mc.text_dim = model_integer(m, file, "mdm", "text_dim", 1, kMaxWidth);
    if (!m.at("mask_frames").is_boolean())
        throw Error(file, "mdm.mask_frames", "true or false", m.at("mask_frames").dump());
    mc.mask_frames = m.at("mask_frames").get<bool>();
    return mc;
}

void load_glove_encoder(MotionModel& model, const std::string& dir, const nlohmann::json& t) {
    const std::string file = dir + "/model.json";
    GloveEncoderConfig tc;
    tc.model_dim = model_integer(t, file, "text_encoder", "model_dim", 1, kMaxWidth);
    tc.layers = model_integer(t, file, "text_encoder", "layers", 1, kMaxLayers);
    tc.heads = model_integer(t, file, "text_encoder", "heads", 1, tc.model_dim);
    if (tc.model_dim % tc.heads != 0)
        throw Error(file, "text_encoder.heads", "a divisor of text_encoder.model_dim", std::to_string(tc.heads));
    tc.ff_size = model_integer(t, file, "text_encoder", "ff_size", 1, kMaxWidth);
    tc.out_dim = model_integer(t, file, "text_encoder", "out_dim", 1, kMaxWidth);
    model.vocab = std::make_unique<WordVectors>(WordVectors::load(find_vocab(dir, t.at("vocab").get<std::string>())));
    model.text = GloveTextEncoder(*model.vocab, tc);
    load_state_dict(*model.text, dir + "/text_encoder.safetensors");
}

// Returns the prefix of CLIP's keys inside weights.safetensors ("clip_model.", MDM's name) when the CLIP weights
// are that same file, so that the MDM loader skips them; "" otherwise.
std::string load_clip_encoder(MotionModel& model, const std::string& dir, const nlohmann::json& t, int64_t text_dim) {
    const std::string weights =
        find_encoder_file(dir, t, "weights", "CLIP's text-tower weights as safetensors (docs/mdm-checkpoint.md)");
    const std::string merges = find_encoder_file(dir, t, "merges", "CLIP's bpe_simple_vocab_16e6.txt.gz");
    ClipTextConfig cc = read_clip_text_config(weights);
    cc.mdm_text_tokens = t.value("text_tokens", cc.mdm_text_tokens);
    if (cc.embed_dim != text_dim)
        throw Error(weights, "text_projection", std::to_string(text_dim) + " outputs (mdm.text_dim)",
                    std::to_string(cc.embed_dim));
    model.clip = ClipTextEncoder(cc);
    load_clip_text_weights(model.clip, weights);
    model.clip->set_tokenizer(std::make_shared<const ClipBpeTokenizer>(ClipBpeTokenizer::from_merges_file(merges)));
    const std::string mdm_weights = dir + "/weights.safetensors";
    return std::filesystem::exists(mdm_weights) && std::filesystem::equivalent(weights, mdm_weights) ? "clip_model."
                                                                                                     : "";
}

void load_minilm_encoder(MotionModel& model, const std::string& dir, const nlohmann::json& t, int64_t text_dim) {
    const std::string file = dir + "/model.json";
    const std::string weights =
        find_encoder_file(dir, t, "weights", "the sentence encoder's BertModel weights as safetensors");
    const std::string vocab = find_encoder_file(dir, t, "vocab", "its WordPiece vocab.txt");
    const BertConfig bc = read_bert_config(weights, model_integer(t, file, "text_encoder", "heads", 1, kMaxWidth));
    if (bc.hidden != text_dim)
        throw Error(weights, "embeddings.word_embeddings.weight", std::to_string(text_dim) + " columns (mdm.text_dim)",
                    std::to_string(bc.hidden));
    const int64_t max_tokens = t.contains("max_tokens")
                                   ? model_integer(t, file, "text_encoder", "max_tokens", 2, bc.max_positions)
                                   : std::min<int64_t>(256, bc.max_positions);
    model.minilm = BertEncoder(bc);
    load_bert_weights(model.minilm, weights);
    model.minilm->set_tokenizer(std::make_shared<const WordPieceTokenizer>(WordPieceTokenizer::from_vocab_file(vocab)),
                                static_cast<size_t>(max_tokens));
}

void load_caption_anchor(MotionModel& model, const std::string& dir, const nlohmann::json& a) {
    const std::string file = dir + "/model.json";
    if (!model.vocab)
        throw Error(file, "caption_anchor",
                    "a glove_transformer text encoder (the anchor searches captions with its GloVe vocabulary)");
    if (!a.is_object() || !a.contains("captions") || !a.at("captions").is_string())
        throw Error(file, "caption_anchor.captions", "a caption file's name");
    model.anchor.neighbours = static_cast<size_t>(model_integer(a, file, "caption_anchor", "neighbours", 1, 1000));
    const nlohmann::json w = a.value("weight", nlohmann::json());
    if (!w.is_number() || !(w.get<double>() >= 0 && w.get<double>() <= 1))
        throw Error(file, "caption_anchor.weight", "a number from 0 to 1", w.dump());
    model.anchor.weight = w.get<double>();
    const nlohmann::json match = a.value("match_attributes", nlohmann::json(false));
    if (!match.is_boolean()) throw Error(file, "caption_anchor.match_attributes", "true or false", match.dump());
    model.anchor.match_attributes = match.get<bool>();
    // Inside the model folder only (a model.json from elsewhere must not make t2imu read /etc/...), and any error
    // of the file names the field that led to it.
    const std::string field = file + ": caption_anchor.captions";
    const std::string captions = confined_path(dir, a.at("captions").get<std::string>(), field);
    try {
        model.anchor.index =
            std::make_unique<CaptionIndex>(*model.vocab, read_prompt_set(captions, PromptActivity::required), captions);
    } catch (const Error& e) {
        throw Error(field + ": " + e.what());
    }
}

}  // namespace

double MotionModel::caption_anchor_weight(std::optional<double> asked) const {
    const double weight = asked.value_or(anchor.weight);
    if (weight > 0 && !anchor.index)
        throw Error("--caption-anchor", "model",
                    "0 (the model folder has no caption anchor: model.json caption_anchor)", std::to_string(weight));
    return weight;
}

torch::Tensor MotionModel::condition(const std::vector<std::string>& prompts,
                                     const std::vector<std::string>& activities, double weight) {
    const torch::Tensor own = encode_text(prompts);
    if (caption_anchor_weight(weight) == 0 || prompts.empty()) return own;
    std::vector<std::string> neighbours;  // prompt-major: K per prompt, fewer when its activity has fewer captions
    std::vector<int64_t> first{0};
    for (size_t i = 0; i < prompts.size(); ++i) {
        for (const CaptionNeighbour& n : anchor.index->nearest(
                 prompts[i], anchor.neighbours, activities.empty() ? "" : activities[i], anchor.match_attributes))
            neighbours.push_back(anchor.index->captions()[n.index].text);
        first.push_back(static_cast<int64_t>(neighbours.size()));
    }
    if (neighbours.empty()) return own;
    const torch::Tensor encoded = encode_text(neighbours);
    std::vector<torch::Tensor> rows;
    for (size_t i = 0; i < prompts.size(); ++i) {
        const torch::Tensor p = own[static_cast<int64_t>(i)];
        // A prompt whose activity is unknown, or has no caption, keeps its own feature.
        rows.push_back(first[i + 1] == first[i]
                           ? p
                           : (1 - weight) * p + weight * encoded.slice(0, first[i], first[i + 1]).mean(0));
    }
    return torch::stack(rows);
}

torch::Tensor MotionModel::encode_text(const std::vector<std::string>& captions) {
    if (clip) return clip->encode(captions);
    if (minilm) return minilm->encode(captions);
    return text->encode(captions);
}

torch::nn::Module& MotionModel::text_module() {
    if (clip) return *clip;
    if (minilm) return *minilm;
    return *text;
}

std::unique_ptr<MotionModel> load_motion_model(const std::string& dir, const std::string& device) {
    auto model = std::make_unique<MotionModel>();
    std::string clip_prefix;
    try {
        model->meta = nlohmann::json::parse(read_file_text(dir + "/model.json"));
        const MdmConfig mc = mdm_config(model->meta.at("mdm"), dir + "/model.json");
        model->mdm = Mdm(mc);
        const auto& t = model->meta.at("text_encoder");
        const std::string kind = t.at("kind").get<std::string>();
        if (kind == "glove_transformer")
            load_glove_encoder(*model, dir, t);
        else if (kind == "clip")
            clip_prefix = load_clip_encoder(*model, dir, t, mc.text_dim);
        else if (kind == "minilm")
            load_minilm_encoder(*model, dir, t, mc.text_dim);
        else
            throw Error(dir + "/model.json", "text_encoder.kind", "glove_transformer, clip or minilm", kind);
        if (model->meta.contains("caption_anchor")) load_caption_anchor(*model, dir, model->meta.at("caption_anchor"));
        model->schedule = cosine_schedule(static_cast<int>(
            model_integer(model->meta.at("diffusion"), dir + "/model.json", "diffusion", "steps", 1, 100000)));
    } catch (const nlohmann::json::exception& e) {
        throw Error(dir + "/model.json", "json", "a t2imu model description", e.what());
    }
    load_mdm_weights(model->mdm, dir + "/weights.safetensors", clip_prefix);
    model->stats = read_feature_stats(dir + "/Mean.npy", dir + "/Std.npy");
    model->device = torch::Device(device);
    model->mdm->to(model->device);
    model->mdm->eval();
    model->text_module().to(model->device);
    model->text_module().eval();
    return model;
}

std::vector<FeatureMatrix> sample_motions(MotionModel& model, const std::vector<std::string>& prompts,
                                          const SampleOptions& o) {
    o.validate();
    if (!o.seeds.empty() && o.seeds.size() != prompts.size())
        throw Error("sample", "seeds", "one seed per prompt", std::to_string(o.seeds.size()));
    if (!o.activities.empty() && o.activities.size() != prompts.size())
        throw Error("sample", "activities", "one activity per prompt", std::to_string(o.activities.size()));
    if (!o.start_motions.empty() && o.start_motions.size() != prompts.size())
        throw Error("sample", "start motions", "one per prompt", std::to_string(o.start_motions.size()));
    torch::NoGradGuard no_grad;
    const GaussianDiffusion diffusion(model.schedule);
    const bool hybrid = !o.start_motions.empty();
    const int t_start =
        hybrid ? static_cast<int>(std::lround(o.strength * (model.schedule.steps - 1))) : model.schedule.steps - 1;
    const int steps = std::min(o.steps, t_start + 1);
    std::vector<FeatureMatrix> out;
    for (size_t start = 0; start < prompts.size(); start += static_cast<size_t>(o.batch)) {
        const size_t n = std::min(prompts.size() - start, static_cast<size_t>(o.batch));
        const std::vector<std::string> batch(prompts.begin() + static_cast<std::ptrdiff_t>(start),
                                             prompts.begin() + static_cast<std::ptrdiff_t>(start + n));
        std::vector<torch::Generator> gens;
        for (size_t i = 0; i < n; ++i)
            gens.push_back(at::detail::createCPUGenerator(o.seeds.empty() ? o.seed + start + i : o.seeds[start + i]));
        const NoiseSource noise = [&gens](const torch::Tensor& like) {
            std::vector<torch::Tensor> rows;
            // Drawn on the CPU whatever the device: a seed gives the same noise on every machine.
            for (size_t i = 0; i < gens.size(); ++i)
                rows.push_back(torch::randn(like[0].sizes(), gens[i], torch::kFloat32));
            return torch::stack(rows).to(like.device());
        };
        torch::Tensor x_T = noise(
            torch::zeros({static_cast<int64_t>(n), 263, 1, o.frames}, torch::TensorOptions().device(model.device)));
        if (hybrid) {
            torch::Tensor x0 = torch::empty({static_cast<int64_t>(n), o.frames, 263}, torch::kFloat64);
            for (size_t i = 0; i < n; ++i) {
                FeatureMatrix f = o.start_motions[start + i];
                for (Eigen::Index c = 0; c < 263; ++c)
                    f.col(c) = ((f.col(c).array() - model.stats.mean[c]) / model.stats.std[c]).matrix();
                std::memcpy(x0[static_cast<int64_t>(i)].data_ptr<double>(), f.data(),
                            sizeof(double) * static_cast<size_t>(o.frames) * 263);
            }
            const double abar = model.schedule.alphas_cumprod[static_cast<size_t>(t_start)];
            x_T = std::sqrt(abar) * x0.to(torch::kFloat32).permute({0, 2, 1}).unsqueeze(2).to(model.device) +
                  std::sqrt(1 - abar) * x_T;
        }
        const std::vector<std::string> activities =
            o.activities.empty()
                ? std::vector<std::string>{}
                : std::vector<std::string>(o.activities.begin() + static_cast<std::ptrdiff_t>(start),
                                           o.activities.begin() + static_cast<std::ptrdiff_t>(start + n));
        const torch::Tensor text = model.condition(batch, activities, model.caption_anchor_weight(o.caption_anchor));
        const torch::Tensor lengths = torch::full({static_cast<int64_t>(n)}, o.frames,
                                                  torch::TensorOptions().dtype(torch::kInt64).device(model.device));
        const X0Predictor denoiser = [&](const torch::Tensor& x, const torch::Tensor& t) {
            return model.mdm->forward_guided(x, t, text, o.guidance, lengths);
        };
        torch::Tensor x0;
        switch (o.sampler) {
            case Sampler::ddpm: x0 = sample_ddpm(diffusion, denoiser, x_T, noise, t_start); break;
            case Sampler::ddim: x0 = sample_ddim(model.schedule, denoiser, x_T, steps, o.eta, noise, t_start); break;
            case Sampler::dpmpp: x0 = sample_dpmpp_2m(model.schedule, denoiser, x_T, steps, t_start); break;
        }
        // Never a non-finite motion out of here: refused at the point it appears, naming what set it off.
        if (!torch::isfinite(x0).all().item<bool>())
            throw Error("sampling", "--guidance", "a scale whose motions stay finite",
                        std::to_string(o.guidance) + " gave inf or NaN features");
        const torch::Tensor frames =
            x0.squeeze(2).permute({0, 2, 1}).to(torch::kCPU, torch::kFloat64).contiguous();  // [n, F, 263], normalised
        for (size_t i = 0; i < n; ++i) {
            FeatureMatrix f(o.frames, 263);
            std::memcpy(f.data(), frames[static_cast<int64_t>(i)].data_ptr<double>(),
                        sizeof(double) * static_cast<size_t>(o.frames) * 263);
            for (Eigen::Index c = 0; c < 263; ++c)
                f.col(c) = (f.col(c).array() * model.stats.std[c] + model.stats.mean[c]).matrix();
            out.push_back(std::move(f));
        }
    }
    return out;
}

}  // namespace t2imu
