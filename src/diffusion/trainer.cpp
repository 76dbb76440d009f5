#include "diffusion/trainer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <set>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/hash.hpp"
#include "core/npy.hpp"
#include "core/output_path.hpp"
#include "core/toml_section.hpp"
#include "data/hml3d_dataset.hpp"
#include "diffusion/gaussian_diffusion.hpp"
#include "diffusion/losses.hpp"
#include "diffusion/recover_from_ric_torch.hpp"
#include "diffusion/text_to_motion.hpp"
#include "motion/skeleton.hpp"
#include "nn/autocast.hpp"
#include "nn/state_dict.hpp"
#include "nn/threads.hpp"
#include "text/training_captions.hpp"

namespace t2imu {

namespace fs = std::filesystem;

// ---------------------------------------------------------------- configuration

namespace {

// The index of an SMPL-22 joint by name (motion/skeleton.hpp), -1 for another name.
int64_t smpl22_joint(const std::string& name) {
    const auto& names = smpl22::kJointNames;
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1 : it - names.begin();
}

// A value of `section` that must lie in [lo, hi] (or above lo when `open_low`); NaN fails every comparison.
void check_range(const std::string& path, const std::string& field, double v, double lo, double hi,
                 bool open_low = false) {
    if (!(open_low ? v > lo : v >= lo) || !(v <= hi)) {
        char range[96];
        std::snprintf(range, sizeof range, "a number %s %g and at most %g", open_low ? "above" : "from", lo, hi);
        throw Error(path, field, range, std::to_string(v));
    }
}

}  // namespace

void TrainConfig::validate(const std::string& path) const {
    if (out.empty()) throw Error(path, "out", "the model folder to write (required)");
    if (dataset.empty()) throw Error(path, "data.dataset", "a dataset folder (required)");
    if (vocab.empty()) throw Error(path, "data.vocab", "the GloVe vocabulary (required)");
    const double big = 1e9;
    check_range(path, "model.latent_dim", static_cast<double>(mdm.latent_dim), 1, 65536);
    check_range(path, "model.ff_size", static_cast<double>(mdm.ff_size), 1, 1 << 20);
    check_range(path, "model.num_layers", static_cast<double>(mdm.num_layers), 1, 256);
    check_range(path, "model.num_heads", static_cast<double>(mdm.num_heads), 1, static_cast<double>(mdm.latent_dim));
    if (mdm.latent_dim % mdm.num_heads != 0)
        throw Error(path, "model.num_heads", "a divisor of model.latent_dim", std::to_string(mdm.num_heads));
    check_range(path, "model.dropout", mdm.dropout, 0, 0.99);
    check_range(path, "text.model_dim", static_cast<double>(text.model_dim), 1, 65536);
    check_range(path, "text.layers", static_cast<double>(text.layers), 1, 256);
    check_range(path, "text.heads", static_cast<double>(text.heads), 1, static_cast<double>(text.model_dim));
    if (text.model_dim % text.heads != 0)
        throw Error(path, "text.heads", "a divisor of text.model_dim", std::to_string(text.heads));
    check_range(path, "text.ff_size", static_cast<double>(text.ff_size), 1, 1 << 20);
    check_range(path, "text.dropout", text.dropout, 0, 0.99);
    check_range(path, "diffusion.steps", diffusion_steps, 2, 100000);
    check_range(path, "train.batch", batch, 1, 1 << 20);
    check_range(path, "train.steps", static_cast<double>(steps), 1, big);
    check_range(path, "train.learning_rate", learning_rate, 0, 1, true);
    check_range(path, "train.weight_decay", weight_decay, 0, 1);
    check_range(path, "train.cond_dropout", cond_dropout, 0, 0.99);
    check_range(path, "train.ema_decay", ema_decay, 0, 0.999999);
    check_range(path, "train.save_every", static_cast<double>(save_every), 1, big);
    check_range(path, "train.log_every", static_cast<double>(log_every), 1, big);
    check_range(path, "loss.lambda_pos", lambda_pos, 0, big);
    check_range(path, "loss.lambda_vel", lambda_vel, 0, big);
    check_range(path, "loss.lambda_foot", lambda_foot, 0, big);
    check_range(path, "loss.lambda_acc", lambda_acc, 0, big);
    if (acc_space != "features" && acc_space != "joints")
        throw Error(path, "loss.acc_space", "features or joints", acc_space);
    if (!acc_joints.empty() && acc_space != "joints")
        throw Error(path, "loss.acc_joints", "acc_space = \"joints\" with it", acc_space);
    std::set<std::string> named;
    for (const std::string& joint : acc_joints)
        if (smpl22_joint(joint) < 0 || !named.insert(joint).second)
            throw Error(path, "loss.acc_joints", "SMPL-22 joint names (pelvis, left_foot, ...), each once", joint);
    parse_precision(precision, path, "train.precision");
    augment.validate(path);
}

TrainConfig read_train_config(const std::string& path) {
    const toml::table doc = parse_toml_file(path);
    TomlSection top(doc, path, "");
    TrainConfig c;
    top.read("out", c.out);
    TomlSection data = top.table("data"), model = top.table("model"), text = top.table("text"),
                diffusion = top.table("diffusion"), train = top.table("train"), loss = top.table("loss"),
                augment = top.table("augment");
    top.refuse_unknown_keys();
    data.read("dataset", c.dataset);
    data.read("vocab", c.vocab);
    data.read("split", c.split);
    model.read("latent_dim", c.mdm.latent_dim);
    model.read("ff_size", c.mdm.ff_size);
    model.read("num_layers", c.mdm.num_layers);
    model.read("num_heads", c.mdm.num_heads);
    model.read("dropout", c.mdm.dropout);
    text.read("model_dim", c.text.model_dim);
    text.read("layers", c.text.layers);
    text.read("heads", c.text.heads);
    text.read("ff_size", c.text.ff_size);
    text.read("dropout", c.text.dropout);
    diffusion.read("steps", c.diffusion_steps);
    train.read("batch", c.batch);
    train.read("steps", c.steps);
    train.read("learning_rate", c.learning_rate);
    train.read("weight_decay", c.weight_decay);
    train.read("cond_dropout", c.cond_dropout);
    train.read("ema_decay", c.ema_decay);
    train.read("seed", c.seed);
    train.read("save_every", c.save_every);
    train.read("log_every", c.log_every);
    train.read("precision", c.precision);
    loss.read("lambda_pos", c.lambda_pos);
    loss.read("lambda_vel", c.lambda_vel);
    loss.read("lambda_foot", c.lambda_foot);
    loss.read("lambda_acc", c.lambda_acc);
    loss.read("acc_space", c.acc_space);
    loss.read("acc_joints", c.acc_joints);
    augment.read("swap", c.augment.swap);
    augment.read("dropout", c.augment.dropout);
    augment.read("neighbours", c.augment.neighbours);
    augment.read("min_similarity", c.augment.min_similarity);
    augment.read("search_words", c.augment.search_words);
    for (const TomlSection* s : {&data, &model, &text, &diffusion, &train, &loss, &augment}) s->refuse_unknown_keys();
    c.validate(path);
    return c;
}

// ---------------------------------------------------------------- losses

LossTerms mdm_loss_terms(const torch::Tensor& x0, const torch::Tensor& x0_hat, const torch::Tensor& lengths,
                         const torch::Tensor& mean, const torch::Tensor& std, const TrainConfig& c) {
    const torch::Tensor mask = frame_mask(lengths, x0.size(1));
    LossTerms t;
    t.simple = masked_mse(x0, x0_hat, mask).mean();
    const bool need_joints = c.lambda_pos > 0 || c.lambda_foot > 0 || (c.lambda_acc > 0 && c.acc_space == "joints");
    torch::Tensor joints, joints_hat;
    if (need_joints) {
        joints = recover_from_ric_torch(x0 * std + mean).flatten(2);  // [B, F, 66]
        joints_hat = recover_from_ric_torch(x0_hat * std + mean).flatten(2);
    }
    const torch::Tensor zero = torch::zeros({}, x0.options());
    t.pos = c.lambda_pos > 0 ? masked_mse(joints, joints_hat, mask).mean() : zero;
    t.vel = c.lambda_vel > 0 ? velocity_mse(x0, x0_hat, mask).mean() : zero;
    if (c.lambda_foot > 0) {
        // Foot joints (left ankle, left foot, right ankle, right foot) and the ground truth's contact flags,
        // the last four feature channels in the same order.
        const torch::Tensor feet = torch::tensor({7, 10, 8, 11}, torch::kInt64).to(x0.device());
        const torch::Tensor j = joints_hat.view({x0.size(0), x0.size(1), 22, 3}).index_select(2, feet);
        const torch::Tensor velocity = j.slice(1, 1) - j.slice(1, 0, -1);  // [B, F-1, 4, 3]
        const torch::Tensor contact = (x0 * std + mean).slice(2, 259, 263).slice(1, 0, -1).gt(0.5).to(x0.dtype());
        const torch::Tensor moving = (velocity * contact.unsqueeze(3)).flatten(2);
        t.foot = masked_mse(torch::zeros_like(moving), moving, mask.slice(1, 1)).mean();
    } else {
        t.foot = zero;
    }
    if (c.lambda_acc > 0 && c.acc_space == "joints" && !c.acc_joints.empty()) {
        std::vector<int64_t> picked;
        for (const std::string& joint : c.acc_joints) picked.push_back(smpl22_joint(joint));
        const torch::Tensor index = torch::tensor(picked, torch::kInt64).to(x0.device());
        const auto some = [&](const torch::Tensor& j) {
            return j.view({x0.size(0), x0.size(1), 22, 3}).index_select(2, index).flatten(2);
        };
        t.acc = acceleration_loss(some(joints), some(joints_hat), mask).mean();
    } else if (c.lambda_acc > 0) {
        t.acc = (c.acc_space == "joints" ? acceleration_loss(joints, joints_hat, mask)
                                         : acceleration_loss(x0, x0_hat, mask))
                    .mean();
    } else {
        t.acc = zero;
    }
    t.total = t.simple + c.lambda_pos * t.pos + c.lambda_vel * t.vel + c.lambda_foot * t.foot + c.lambda_acc * t.acc;
    return t;
}

// ---------------------------------------------------------------- weights and checkpoints

namespace {

torch::Tensor text_tensor(const std::string& s) {
    return torch::from_blob(const_cast<char*>(s.data()), {static_cast<int64_t>(s.size())}, torch::kUInt8).clone();
}
std::string tensor_text(const torch::Tensor& t) {
    const torch::Tensor c = t.contiguous();
    return std::string(reinterpret_cast<const char*>(c.data_ptr<uint8_t>()), static_cast<size_t>(c.numel()));
}

struct Training {
    Mdm mdm{nullptr};
    GloveTextEncoder text{nullptr};
    std::unique_ptr<torch::optim::AdamW> optimiser;
    std::vector<torch::Tensor> ema;  // one per parameter of mdm then text, or empty
    torch::Generator generator;
    std::mt19937_64 dropout_rng;
    int64_t step = 0;

    std::vector<torch::Tensor> parameters() const {
        std::vector<torch::Tensor> p = mdm->parameters();
        for (const torch::Tensor& t : text->parameters()) p.push_back(t);
        return p;
    }
};

std::string shape_text(c10::IntArrayRef s) { return c10::str(s); }  // "[512, 263]"

// checkpoint.pt holds two entries: "state", the training state serialised by libtorch (bytes), and "fnv1a64",
// FNV-1a of those bytes. A damaged file (a flipped block of the same size) is refused on load, never resumed
// from: resuming from garbage gives NaN weights that the next save would write over the model.
void save_checkpoint(Training& tr, const Hml3dDataset& data, const std::string& path) {
    torch::serialize::OutputArchive archive;
    for (const auto& p : tr.mdm->named_parameters()) archive.write("mdm." + p.key(), p.value());
    for (const auto& p : tr.text->named_parameters()) archive.write("text." + p.key(), p.value());
    torch::serialize::OutputArchive optimiser;
    tr.optimiser->save(optimiser);
    archive.write("optimiser", optimiser);
    for (size_t i = 0; i < tr.ema.size(); ++i) archive.write("ema." + std::to_string(i), tr.ema[i]);
    archive.write("step", torch::tensor(tr.step));
    archive.write("generator", tr.generator.get_state());
    archive.write("default_generator", at::detail::getDefaultCPUGenerator().get_state());  // dropout draws on the CPU
    std::ostringstream rng;
    rng << tr.dropout_rng;
    archive.write("dropout_rng", text_tensor(rng.str()));
    archive.write("dataset", text_tensor(data.state()));
    std::ostringstream bytes;
    archive.save_to(bytes);
    const std::string state = bytes.str();
    torch::serialize::OutputArchive file;
    file.write("state", text_tensor(state));
    file.write("fnv1a64", torch::tensor(static_cast<int64_t>(fnv1a64(state))));
    const std::string tmp = temporary_path_for(path);
    file.save_to(tmp);
    commit_temporary(tmp, path);
}

// The first line of a libtorch error, without its C++ stack trace.
std::string first_line(const c10::Error& e) {
    const std::string m = e.what_without_backtrace();
    return m.substr(0, std::min(m.find('\n'), size_t{300}));
}

// The training state's bytes from checkpoint.pt, checked against their checksum.
std::string verified_checkpoint_state(const std::string& path) {
    torch::serialize::InputArchive file;
    try {
        file.load_from(path, torch::Device(torch::kCPU));
    } catch (const c10::Error& e) {
        throw Error(path, "checkpoint", "a checkpoint libtorch can read (cut or damaged?)", first_line(e));
    }
    torch::Tensor state, sum;
    if (!file.try_read("state", state) || !file.try_read("fnv1a64", sum) || state.scalar_type() != torch::kUInt8 ||
        sum.numel() != 1)
        throw Error(path, "state", "a checkpoint of this version of t2imu (a state and its fnv1a64 checksum)");
    std::string bytes = tensor_text(state);
    const uint64_t expected = static_cast<uint64_t>(sum.item<int64_t>()), got = fnv1a64(bytes);
    if (expected != got)
        throw Error(path, "fnv1a64",
                    "the checksum of its state (the file is damaged: resume from a copy, or train afresh)",
                    std::to_string(got) + " against " + std::to_string(expected));
    return bytes;
}

void load_checkpoint(Training& tr, Hml3dDataset& data, const std::string& path, const torch::Device& device) {
    const std::string bytes = verified_checkpoint_state(path);
    torch::serialize::InputArchive archive;
    std::string key = "state";
    try {
        archive.load_from(bytes.data(), bytes.size(),
                          device);  // a checkpoint written on a GPU resumes on the CPU, and back
        torch::NoGradGuard no_grad;
        // A fresh tensor per read: the archive's storage cannot be resized into another shape.
        const auto read = [&](const std::string& name) {
            key = name;
            torch::Tensor t;
            archive.read(name, t);
            return t;
        };
        // A parameter of another shape is another model configuration: named, not left to copy_'s stack trace.
        const auto restore = [&](torch::Tensor& into, const std::string& name) {
            const torch::Tensor t = read(name);
            if (t.sizes() != into.sizes())
                throw Error(path, name, "shape " + shape_text(into.sizes()) + " (the config's model)",
                            shape_text(t.sizes()));
            into.copy_(t);
        };
        for (auto& p : tr.mdm->named_parameters()) restore(p.value(), "mdm." + p.key());
        for (auto& p : tr.text->named_parameters()) restore(p.value(), "text." + p.key());
        key = "optimiser";
        torch::serialize::InputArchive optimiser;
        archive.read("optimiser", optimiser);
        tr.optimiser->load(optimiser);
        for (size_t i = 0; i < tr.ema.size(); ++i) restore(tr.ema[i], "ema." + std::to_string(i));
        tr.step = read("step").item<int64_t>();
        tr.generator.set_state(read("generator").to(torch::kCPU));
        at::Generator global = at::detail::getDefaultCPUGenerator();  // a handle sharing the default generator
        global.set_state(read("default_generator").to(torch::kCPU));
        std::istringstream rng(tensor_text(read("dropout_rng")));
        rng >> tr.dropout_rng;
        key = "dataset";
        data.restore_state(tensor_text(read("dataset")));
    } catch (const c10::Error& e) {
        throw Error(path, key, "the training state this config makes", first_line(e));
    }
    for (const torch::Tensor& p : tr.parameters())
        if (!torch::isfinite(p).all().item<bool>())
            throw Error(path, "parameters", "finite weights", "NaN or infinite values");
}

void write_model(const Training& tr, const TrainConfig& c, const Hml3dDataset& data) {
    fs::create_directories(c.out);
    // EMA weights, when kept, are the model's weights (they sample better); the raw ones stay in the checkpoint.
    std::vector<torch::Tensor> saved;
    const std::vector<torch::Tensor> params = tr.parameters();
    if (!tr.ema.empty()) {
        torch::NoGradGuard no_grad;
        for (size_t i = 0; i < params.size(); ++i) {
            saved.push_back(params[i].detach().clone());
            params[i].copy_(tr.ema[i]);
        }
    }
    save_state_dict(*tr.mdm, c.out + "/weights.safetensors");
    save_state_dict(*tr.text, c.out + "/text_encoder.safetensors");
    if (!saved.empty()) {
        torch::NoGradGuard no_grad;
        for (size_t i = 0; i < params.size(); ++i) params[i].copy_(saved[i]);
    }
    const FeatureStats& s = data.stats();
    const std::vector<double> mean(s.mean.data(), s.mean.data() + s.mean.size()),
        sd(s.std.data(), s.std.data() + s.std.size());
    write_npy(c.out + "/Mean.npy", NdArray::from(mean, {static_cast<int64_t>(mean.size())}));
    write_npy(c.out + "/Std.npy", NdArray::from(sd, {static_cast<int64_t>(sd.size())}));
    const MdmConfig& m = tr.mdm->config();
    const nlohmann::json model = {
        {"architecture", "mdm_trans_enc"},
        {"mdm",
         {{"njoints", m.njoints},
          {"latent_dim", m.latent_dim},
          {"ff_size", m.ff_size},
          {"num_layers", m.num_layers},
          {"num_heads", m.num_heads},
          {"dropout", m.dropout},
          {"text_dim", m.text_dim},
          {"mask_frames", m.mask_frames}}},
        {"text_encoder",
         {{"kind", "glove_transformer"},
          {"vocab", c.vocab},
          {"model_dim", c.text.model_dim},
          {"layers", c.text.layers},
          {"heads", c.text.heads},
          {"ff_size", c.text.ff_size},
          {"out_dim", c.text.out_dim}}},
        {"diffusion", {{"schedule", "cosine"}, {"steps", c.diffusion_steps}, {"predict", "x0"}}},
        {"normalisation", {{"mean", "Mean.npy"}, {"std", "Std.npy"}}},
        {"training",
         {{"dataset", c.dataset},
          {"step", tr.step},
          {"ema", c.ema_decay > 0},
          {"precision", c.precision},
          {"lambda_pos", c.lambda_pos},
          {"lambda_vel", c.lambda_vel},
          {"lambda_foot", c.lambda_foot},
          {"lambda_acc", c.lambda_acc},
          {"acc_space", c.acc_space},
          {"acc_joints", c.acc_joints},
          {"augment",
           {{"swap", c.augment.swap},
            {"dropout", c.augment.dropout},
            {"neighbours", c.augment.neighbours},
            {"min_similarity", c.augment.min_similarity},
            {"search_words", c.augment.search_words}}}}},
        {"caption_anchor",
         {{"captions", "captions.tsv"}, {"neighbours", kCaptionAnchorNeighbours}, {"weight", kCaptionAnchorWeight}}}};
    write_training_captions(c.out + "/captions.tsv", training_captions(data, c.dataset));
    write_file_atomic(c.out + "/model.json", model.dump(2) + "\n");
}

}  // namespace

// ---------------------------------------------------------------- the loop

namespace {

std::atomic<bool> g_stop_requested{false};

// The draws of t and of the noise. On a GPU they come from the device's default generator, which also drives
// the model's dropout there, so one saved state covers both; on the CPU from a generator of their own. Over
// several processes always from a CPU generator of their own: every rank replays the same draws, while the
// model's dropout (the device's default generator) draws per rank.
torch::Generator noise_generator(const torch::Device& device, uint64_t seed, bool several_processes) {
    if (device.is_cpu() || several_processes) return at::detail::createCPUGenerator(seed);
    at::Generator g = at::globalContext().defaultGenerator(device);
    g.set_current_seed(seed);
    return g;
}

// A rank's own stream for the model's dropout masks (splitmix64 of seed, rank and the starting step), so the
// ranks do not drop the same units in their different samples.
void seed_rank_dropout(const torch::Device& device, uint64_t seed, int rank, int64_t step) {
    const uint64_t z = splitmix64(seed + 0x9E3779B97F4A7C15ull * (static_cast<uint64_t>(rank) + 1) +
                                  0xBF58476D1CE4E5B9ull * static_cast<uint64_t>(step));
    at::Generator dropout =
        device.is_cpu() ? at::detail::getDefaultCPUGenerator() : at::globalContext().defaultGenerator(device);
    dropout.set_current_seed(z);  // a handle sharing the default generator
}

// "cuda" alone means the GPU of this process's LOCAL_RANK when several processes share a machine.
torch::Device training_device(const std::string& name, const ProcessGroupEnv& processes) {
    if (name == "cuda" && processes.world_size > 1)
        return torch::Device(torch::kCUDA, static_cast<c10::DeviceIndex>(processes.local_rank));
    return torch::Device(name);
}

std::vector<std::string> all_captions(const Hml3dDataset& data) {
    std::vector<std::string> out;
    for (const MotionClip& clip : data.clips())
        for (const CaptionLine& line : clip.captions) out.push_back(line.caption);
    return out;
}

// Wall time per part of a step. With `synchronise` on a GPU each part first waits for the kernels it queued,
// so their time lands on it (at the price of the overlap); on the CPU every part already ends when it returns.
class PartClock {
public:
    StepProfile parts;
    PartClock(const torch::Device& device, bool synchronise) : synchronise_(device.is_cuda() && synchronise) {}
    void start_step(bool counted) {
        counted_ = counted;
        parts.steps += counted ? 1 : 0;
        last_ = std::chrono::steady_clock::now();
    }
    void lap(double& part) {
        if (synchronise_) torch::cuda::synchronize();
        const auto now = std::chrono::steady_clock::now();
        if (counted_) part += std::chrono::duration<double>(now - last_).count();
        last_ = now;
    }

private:
    bool synchronise_, counted_ = false;
    std::chrono::steady_clock::time_point last_;
};

// ema <- decay ema + (1 - decay) p over all parameters at once (one kernel per list, not two per tensor).
void update_ema(Training& tr, double decay) {
    torch::NoGradGuard no_grad;
    std::vector<torch::Tensor> params;
    for (const torch::Tensor& p : tr.parameters()) params.push_back(p.detach());
    torch::_foreach_mul_(tr.ema, decay);
    torch::_foreach_add_(tr.ema, params, 1 - decay);
}

// Slots of the values that ride along with the gradients' all-reduce.
enum Rider : int64_t { kSimple, kPos, kVel, kFoot, kAcc, kTotal, kStop };

// The model and text encoder, initialised from the configuration's seed (so every rank builds the same weights)
// or loaded from a model folder (a fine-tuning), on the device; the optimiser and EMA come after the broadcast.
Training new_training(const TrainConfig& c, const WordVectors& vocab, const torch::Device& device,
                      const std::string& init_from) {
    torch::manual_seed(c.seed);
    MdmConfig mc = c.mdm;
    mc.text_dim = c.text.out_dim;
    mc.mask_frames = true;
    Training tr{Mdm(mc),
                GloveTextEncoder(vocab, c.text),
                nullptr,
                {},
                noise_generator(device, c.seed, c.processes.world_size > 1),
                std::mt19937_64(c.seed + 1),
                0};
    if (!init_from.empty()) {
        load_state_dict(*tr.mdm, init_from + "/weights.safetensors");
        load_state_dict(*tr.text, init_from + "/text_encoder.safetensors");
    }
    tr.mdm->to(device);
    tr.text->to(device);
    return tr;
}

// Everything a run keeps fixed from its first step to its last, beside the Training state.
struct RunSetup {
    BatchShare share;  // this rank's samples of the global batch
    torch::Device device;
    torch::TensorOptions draws_on;  // where t and the noise are drawn: the CPU when several ranks must agree
    GaussianDiffusion diffusion;
    torch::Tensor mean, std;  // the dataset's feature statistics on the device (the losses de-normalise)
    Precision precision;
    std::bernoulli_distribution drop;        // classifier-free guidance's caption dropout
    std::optional<CaptionAugmenter> reword;  // caption augmentation, when configured
};

RunSetup run_setup(const TrainConfig& c, const Hml3dDataset& data, const WordVectors& vocab, const BatchShare& share,
                   const torch::Device& device) {
    const bool several = c.processes.world_size > 1;
    const auto on_device = [&](const Eigen::VectorXd& v) {
        return torch::from_blob(const_cast<double*>(v.data()), {263}, torch::kFloat64).to(device, torch::kFloat32);
    };
    RunSetup run{share,
                 device,
                 torch::TensorOptions().device(several ? torch::Device(torch::kCPU) : device),
                 GaussianDiffusion(cosine_schedule(c.diffusion_steps)),
                 on_device(data.stats().mean),
                 on_device(data.stats().std),
                 parse_precision(c.precision, "train config", "train.precision"),
                 std::bernoulli_distribution(c.cond_dropout),
                 std::nullopt};
    if (c.augment.enabled()) run.reword.emplace(vocab, c.augment, all_captions(data));
    return run;
}

// One step's inputs: this rank's share of the global batch, its captions (dropped or reworded) and x0 noised
// to x_t at the drawn steps t. Every rank draws the whole batch's captions, t and noise, so the ranks' streams
// stay equal; the order of the draws is part of the checkpoint's contract (resume continues the same stream).
struct StepBatch {
    Batch drawn;                        // the global batch; x0 views its features on the CPU, so it lives here
    torch::Tensor x0, x_t, t, lengths;  // x0 [n, F, 263] normalised; x_t [n, 263, 1, F] (MDM's layout)
    std::vector<std::string> captions;
};

StepBatch draw_step_batch(Training& tr, Hml3dDataset& data, const TrainConfig& c, RunSetup& run) {
    StepBatch s;
    s.drawn = data.next_batch(c.batch);
    const Batch& b = s.drawn;
    std::vector<std::string> captions = b.captions;
    for (std::string& caption : captions)
        if (run.drop(tr.dropout_rng))
            caption.clear();
        else if (run.reword)
            caption = run.reword->augment(caption, tr.dropout_rng);  // same stream: saved with the checkpoint
    const torch::Tensor t_all =
        torch::randint(c.diffusion_steps, {b.size}, tr.generator, run.draws_on.dtype(torch::kInt64));
    const torch::Tensor noise_all = torch::randn({b.size, b.channels, 1, b.frames}, tr.generator, run.draws_on);
    const int64_t lo = run.share.begin, n = run.share.size;
    const float* features = b.features.data() + static_cast<size_t>(lo) * static_cast<size_t>(b.frames * b.channels);
    s.x0 = torch::from_blob(const_cast<float*>(features), {n, b.frames, b.channels}, torch::kFloat32).to(run.device);
    s.lengths = torch::tensor(std::vector<int64_t>(b.lengths.begin() + lo, b.lengths.begin() + lo + n)).to(run.device);
    s.captions.assign(captions.begin() + lo, captions.begin() + lo + n);
    s.t = t_all.slice(0, lo, lo + n).to(run.device);
    s.x_t = run.diffusion.q_sample(s.x0.permute({0, 2, 1}).unsqueeze(2), s.t,
                                   noise_all.slice(0, lo, lo + n).to(run.device));
    return s;
}

// Forward, losses, backward and the all-reduce that carries the loss terms and the stop flag (riders, in Rider
// order, on the CPU), then the optimiser and EMA. Times each part on `clock`.
std::vector<double> train_step(Training& tr, const StepBatch& s, const TrainConfig& c, const RunSetup& run,
                               const DataParallel& group, bool out_of_time, PartClock& clock) {
    // The text encoder (libtorch's own layers, a few tokens) stays in fp32; MDM's products run in bf16 when
    // asked, its output and the losses below in fp32.
    const torch::Tensor text = tr.text->encode(s.captions);
    clock.lap(clock.parts.text);
    torch::Tensor x0_hat;
    {
        const AutocastScope mixed(run.device, run.precision);
        x0_hat = tr.mdm->forward(s.x_t, s.t, text, false, s.lengths).squeeze(2).permute({0, 2, 1}).to(torch::kFloat32);
    }
    // Every term is a mean over the share of per-sample means (each normalised by its own valid frames,
    // losses.hpp), so the ranks' mean of equal shares is the global batch's mean: no normaliser to share.
    const LossTerms terms = mdm_loss_terms(s.x0, x0_hat, s.lengths, run.mean, run.std, c);
    clock.lap(clock.parts.forward);
    tr.optimiser->zero_grad();
    terms.total.backward();
    const torch::Tensor stop_flag = torch::full({1}, g_stop_requested || out_of_time ? 1.0f : 0.0f, s.x0.options());
    const torch::Tensor losses = torch::stack({terms.simple, terms.pos, terms.vel, terms.foot, terms.acc, terms.total})
                                     .detach()
                                     .to(torch::kFloat32);
    const torch::Tensor riders = group.average_gradients(tr.parameters(), torch::cat({losses, stop_flag}))
                                     .to(torch::kCPU, torch::kFloat64)
                                     .contiguous();
    clock.lap(clock.parts.backward);
    tr.optimiser->step();
    clock.lap(clock.parts.optimiser);
    if (!tr.ema.empty()) update_ema(tr, ema_decay_at(c.ema_decay, tr.step));
    clock.lap(clock.parts.ema);
    return std::vector<double>(riders.data_ptr<double>(), riders.data_ptr<double>() + riders.numel());
}

// Rank 0's log line (stderr and the metrics buffer) and, every save_every steps, the metrics appended, the
// checkpoint and the model folder; whether it saved.
bool log_and_save(Training& tr, const Hml3dDataset& data, const TrainConfig& c, const std::vector<double>& r,
                  double seconds, int64_t first, bool last_step, std::string* metrics) {
    if (tr.step % c.log_every == 0 || last_step) {
        const double rate = static_cast<double>(tr.step - first) / std::max(seconds, 1e-9);
        const nlohmann::json line = {{"step", tr.step},  {"loss", r[kTotal]},  {"l_simple", r[kSimple]},
                                     {"l_pos", r[kPos]}, {"l_vel", r[kVel]},   {"l_foot", r[kFoot]},
                                     {"l_acc", r[kAcc]}, {"steps_per_s", rate}};
        *metrics += line.dump() + "\n";
        std::fprintf(stderr, "step %lld/%lld loss %.4f (simple %.4f acc %.4f) %.2f steps/s ETA %.0f s\n",
                     static_cast<long long>(tr.step), static_cast<long long>(c.steps), r[kTotal], r[kSimple], r[kAcc],
                     rate, static_cast<double>(c.steps - tr.step) / std::max(rate, 1e-9));
    }
    if (tr.step % c.save_every == 0 || last_step) {
        std::string previous;
        if (fs::exists(c.out + "/metrics.jsonl")) previous = read_file_text(c.out + "/metrics.jsonl");
        write_file_atomic(c.out + "/metrics.jsonl", previous + *metrics);
        metrics->clear();
        save_checkpoint(tr, data, c.out + "/checkpoint.pt");
        write_model(tr, c, data);
        return true;
    }
    return false;
}

}  // namespace

void request_training_stop() { g_stop_requested = true; }

double ema_decay_at(double max_decay, int64_t step) {
    return std::min(max_decay, (1.0 + static_cast<double>(step)) / (10.0 + static_cast<double>(step)));
}

TrainProgress train_mdm(const TrainConfig& c, bool resume, const std::string& init_from, int64_t stop_after) {
    // Refused before anything waits for the other ranks.
    const BatchShare share = batch_share(c.batch, c.processes.rank, c.processes.world_size);
    if (c.threads > 0) set_torch_threads(c.threads);
    Hml3dDataset data(c.dataset, c.split);
    if (data.clips().empty())
        throw Error(c.dataset, c.split, "at least one usable clip (40 to 199 frames with a caption)");
    // The feature space a run trains in: a fine-tuning's base model's (its weights were fitted to it, and a dataset
    // rebuilt with more clips has a slightly different Mean/Std), a resumed run's own as it saved it, else the
    // dataset's. The model folder written holds the same.
    const std::string checkpoint =
        c.out + "/checkpoint.pt";  // asked for first: it, not Mean.npy, is what a resume needs
    if (resume && !fs::exists(checkpoint))
        throw Error(checkpoint, "file", "a checkpoint to resume from (train without --resume to start)");
    const std::string stats_from = resume ? c.out : init_from;
    if (!stats_from.empty()) data.use_stats(read_feature_stats(stats_from + "/Mean.npy", stats_from + "/Std.npy"));
    data.seed(c.seed);
    const WordVectors vocab = WordVectors::load(c.vocab);
    const torch::Device device = training_device(c.device, c.processes);
    Training tr = new_training(c, vocab, device, init_from);
    const DataParallel group(c.processes, device);
    group.broadcast_from_main(tr.parameters());  // the same seed already gave the same weights: this makes sure
    tr.optimiser = std::make_unique<torch::optim::AdamW>(
        tr.parameters(), torch::optim::AdamWOptions(c.learning_rate).weight_decay(c.weight_decay));
    if (c.ema_decay > 0)
        for (const torch::Tensor& p : tr.parameters()) tr.ema.push_back(p.detach().clone());
    if (group.is_main())
        claim_output_folder(c.out);  // marked as t2imu's: --resume continues in it (core/output_path.hpp)
    if (resume) load_checkpoint(tr, data, checkpoint, device);
    if (c.processes.world_size > 1) seed_rank_dropout(device, c.seed, group.rank(), tr.step);
    RunSetup run = run_setup(c, data, vocab, share, device);
    std::string metrics;
    TrainProgress progress;
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed_s = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const int64_t first = tr.step, last = stop_after > 0 ? std::min(c.steps, tr.step + stop_after) : c.steps;
    int64_t last_saved = first;  // the step the model folder holds (0: nothing saved yet)
    g_stop_requested = false;
    bool stop = false;
    PartClock clock(device, c.profile);
    while (tr.step < last && !stop) {
        clock.start_step(tr.step > first);  // the call's first step builds kernels and caches: not profiled
        const StepBatch batch = draw_step_batch(tr, data, c, run);
        clock.lap(clock.parts.data);
        const bool out_of_time = c.max_minutes > 0 && elapsed_s() >= 60 * c.max_minutes;
        const std::vector<double> r = train_step(tr, batch, c, run, group, out_of_time, clock);
        stop = r[kStop] > 0;  // any rank's request stops all of them after the same step
        ++tr.step;
        // Every rank sees the same reduced loss, so all stop here; the step's update is never saved.
        if (!std::isfinite(r[kTotal]))
            throw Error(c.out, "step " + std::to_string(tr.step),
                        last_saved > 0 ? "a finite loss (training stopped; the model folder stays at step " +
                                             std::to_string(last_saved) + ")"
                                       : std::string("a finite loss (training stopped before anything was saved)"),
                        std::to_string(r[kTotal]));
        progress.loss = r[kTotal];
        ++progress.steps_run;
        if (!group.is_main()) continue;
        if (log_and_save(tr, data, c, r, elapsed_s(), first, tr.step == last || stop, &metrics)) last_saved = tr.step;
        clock.lap(clock.parts.log);
    }
    progress.profile = clock.parts;
    group.barrier();  // the other ranks return once rank 0's files are written
    progress.step = tr.step;
    progress.stopped_early = tr.step < last;
    return progress;
}

}  // namespace t2imu
