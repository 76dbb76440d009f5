#include "diffusion/trainer.hpp"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "data/hml3d_dataset.hpp"
#include "diffusion/gaussian_diffusion.hpp"
#include "diffusion/losses.hpp"
#include "diffusion/recover_from_ric_torch.hpp"
#include "nn/state_dict.hpp"
#include "nn/threads.hpp"

namespace t2imu {

namespace fs = std::filesystem;

// ---------------------------------------------------------------- configuration

namespace {

template <class T> void take(const toml::table& t, const char* key, T& value, std::set<std::string>& seen, const std::string& section) {
    seen.insert(key);
    if (const toml::node* n = t.get(key)) {
        const auto v = n->value<T>();
        if (!v) throw Error("config", section + "." + key, "a value of the right type");
        value = *v;
    }
}

void refuse_unknown(const toml::table& t, const std::set<std::string>& known, const std::string& section, const std::string& path) {
    for (const auto& [k, v] : t)
        if (!known.count(std::string(k.str()))) throw Error(path, section + "." + std::string(k.str()), "a known key");
}

}  // namespace

TrainConfig read_train_config(const std::string& path) {
    toml::table doc;
    try {
        doc = toml::parse_file(path);
    } catch (const toml::parse_error& e) {
        throw Error(path, "toml", "a valid TOML file", std::string(e.description()));
    }
    TrainConfig c;
    std::set<std::string> top = {"out", "data", "model", "text", "diffusion", "train", "loss"};
    refuse_unknown(doc, top, "", path);
    if (auto out = doc["out"].value<std::string>()) c.out = *out;
    const auto section = [&](const char* name) { return doc[name].as_table() ? *doc[name].as_table() : toml::table{}; };
    std::set<std::string> seen;
    const toml::table data = section("data"), model = section("model"), text = section("text"), diffusion = section("diffusion"),
                      train = section("train"), loss = section("loss");
    take(data, "dataset", c.dataset, seen, "data");
    take(data, "vocab", c.vocab, seen, "data");
    take(data, "split", c.split, seen, "data");
    refuse_unknown(data, seen, "data", path);
    seen.clear();
    take(model, "latent_dim", c.mdm.latent_dim, seen, "model");
    take(model, "ff_size", c.mdm.ff_size, seen, "model");
    take(model, "num_layers", c.mdm.num_layers, seen, "model");
    take(model, "num_heads", c.mdm.num_heads, seen, "model");
    take(model, "dropout", c.mdm.dropout, seen, "model");
    refuse_unknown(model, seen, "model", path);
    seen.clear();
    take(text, "model_dim", c.text.model_dim, seen, "text");
    take(text, "layers", c.text.layers, seen, "text");
    take(text, "heads", c.text.heads, seen, "text");
    take(text, "ff_size", c.text.ff_size, seen, "text");
    take(text, "dropout", c.text.dropout, seen, "text");
    refuse_unknown(text, seen, "text", path);
    seen.clear();
    int64_t steps = c.diffusion_steps;
    take(diffusion, "steps", steps, seen, "diffusion");
    c.diffusion_steps = static_cast<int>(steps);
    refuse_unknown(diffusion, seen, "diffusion", path);
    seen.clear();
    int64_t batch = c.batch, seed = static_cast<int64_t>(c.seed);
    take(train, "batch", batch, seen, "train");
    take(train, "steps", c.steps, seen, "train");
    take(train, "learning_rate", c.learning_rate, seen, "train");
    take(train, "weight_decay", c.weight_decay, seen, "train");
    take(train, "cond_dropout", c.cond_dropout, seen, "train");
    take(train, "ema_decay", c.ema_decay, seen, "train");
    take(train, "seed", seed, seen, "train");
    take(train, "save_every", c.save_every, seen, "train");
    take(train, "log_every", c.log_every, seen, "train");
    refuse_unknown(train, seen, "train", path);
    c.batch = static_cast<int>(batch);
    c.seed = static_cast<uint64_t>(seed);
    seen.clear();
    take(loss, "lambda_pos", c.lambda_pos, seen, "loss");
    take(loss, "lambda_vel", c.lambda_vel, seen, "loss");
    take(loss, "lambda_foot", c.lambda_foot, seen, "loss");
    take(loss, "lambda_acc", c.lambda_acc, seen, "loss");
    take(loss, "acc_space", c.acc_space, seen, "loss");
    refuse_unknown(loss, seen, "loss", path);
    if (c.dataset.empty() || c.vocab.empty() || c.out.empty()) throw Error(path, "data", "out, data.dataset and data.vocab");
    if (c.acc_space != "features" && c.acc_space != "joints") throw Error(path, "loss.acc_space", "features or joints", c.acc_space);
    if (c.batch < 1 || c.steps < 1 || c.diffusion_steps < 2) throw Error(path, "train", "batch >= 1, steps >= 1, diffusion.steps >= 2");
    return c;
}

// ---------------------------------------------------------------- losses

LossTerms mdm_loss_terms(const torch::Tensor& x0, const torch::Tensor& x0_hat, const torch::Tensor& lengths, const torch::Tensor& mean,
                         const torch::Tensor& std, const TrainConfig& c) {
    const torch::Tensor mask = frame_mask(lengths, x0.size(1));
    LossTerms t;
    t.simple = masked_mse(x0, x0_hat, mask).mean();
    const bool need_joints = c.lambda_pos > 0 || c.lambda_foot > 0 || (c.lambda_acc > 0 && c.acc_space == "joints");
    torch::Tensor joints, joints_hat;
    if (need_joints) {
        joints = recover_from_ric_torch(x0 * std + mean).flatten(2);        // [B, F, 66]
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
        const torch::Tensor velocity = j.slice(1, 1) - j.slice(1, 0, -1);                     // [B, F-1, 4, 3]
        const torch::Tensor contact = (x0 * std + mean).slice(2, 259, 263).slice(1, 0, -1).gt(0.5).to(x0.dtype());
        const torch::Tensor moving = (velocity * contact.unsqueeze(3)).flatten(2);
        t.foot = masked_mse(torch::zeros_like(moving), moving, mask.slice(1, 1)).mean();
    } else {
        t.foot = zero;
    }
    if (c.lambda_acc > 0)
        t.acc = (c.acc_space == "joints" ? acceleration_loss(joints, joints_hat, mask) : acceleration_loss(x0, x0_hat, mask)).mean();
    else
        t.acc = zero;
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
    const std::string tmp = temporary_path_for(path);
    archive.save_to(tmp);
    commit_temporary(tmp, path);
}

void load_checkpoint(Training& tr, Hml3dDataset& data, const std::string& path, const torch::Device& device) {
    torch::serialize::InputArchive archive;
    archive.load_from(path, device);  // a checkpoint written on a GPU resumes on the CPU, and back
    torch::NoGradGuard no_grad;
    // A fresh tensor per read: the archive's storage cannot be resized into another shape.
    const auto read = [&](const std::string& key) {
        torch::Tensor t;
        archive.read(key, t);
        return t;
    };
    for (auto& p : tr.mdm->named_parameters()) p.value().copy_(read("mdm." + p.key()));
    for (auto& p : tr.text->named_parameters()) p.value().copy_(read("text." + p.key()));
    torch::serialize::InputArchive optimiser;
    archive.read("optimiser", optimiser);
    tr.optimiser->load(optimiser);
    for (size_t i = 0; i < tr.ema.size(); ++i) tr.ema[i].copy_(read("ema." + std::to_string(i)));
    tr.step = read("step").item<int64_t>();
    tr.generator.set_state(read("generator").to(torch::kCPU));
    at::Generator global = at::detail::getDefaultCPUGenerator();  // a handle sharing the default generator
    global.set_state(read("default_generator").to(torch::kCPU));
    std::istringstream rng(tensor_text(read("dropout_rng")));
    rng >> tr.dropout_rng;
    data.restore_state(tensor_text(read("dataset")));
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
    const std::vector<double> mean(s.mean.data(), s.mean.data() + s.mean.size()), sd(s.std.data(), s.std.data() + s.std.size());
    write_npy(c.out + "/Mean.npy", NdArray::from(mean, {static_cast<int64_t>(mean.size())}));
    write_npy(c.out + "/Std.npy", NdArray::from(sd, {static_cast<int64_t>(sd.size())}));
    const MdmConfig& m = tr.mdm->config();
    const nlohmann::json model = {
        {"architecture", "mdm_trans_enc"},
        {"mdm", {{"njoints", m.njoints}, {"latent_dim", m.latent_dim}, {"ff_size", m.ff_size}, {"num_layers", m.num_layers},
                 {"num_heads", m.num_heads}, {"dropout", m.dropout}, {"text_dim", m.text_dim}, {"mask_frames", m.mask_frames}}},
        {"text_encoder", {{"kind", "glove_transformer"}, {"vocab", c.vocab}, {"model_dim", c.text.model_dim},
                          {"layers", c.text.layers}, {"heads", c.text.heads}, {"ff_size", c.text.ff_size}, {"out_dim", c.text.out_dim}}},
        {"diffusion", {{"schedule", "cosine"}, {"steps", c.diffusion_steps}, {"predict", "x0"}}},
        {"normalisation", {{"mean", "Mean.npy"}, {"std", "Std.npy"}}},
        {"training", {{"dataset", c.dataset}, {"step", tr.step}, {"ema", c.ema_decay > 0}, {"lambda_pos", c.lambda_pos},
                      {"lambda_vel", c.lambda_vel}, {"lambda_foot", c.lambda_foot}, {"lambda_acc", c.lambda_acc}, {"acc_space", c.acc_space}}}};
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
    uint64_t z = seed + 0x9E3779B97F4A7C15ull * (static_cast<uint64_t>(rank) + 1) + 0xBF58476D1CE4E5B9ull * static_cast<uint64_t>(step);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    at::Generator dropout = device.is_cpu() ? at::detail::getDefaultCPUGenerator() : at::globalContext().defaultGenerator(device);
    dropout.set_current_seed(z);  // a handle sharing the default generator
}

// "cuda" alone means the GPU of this process's LOCAL_RANK when several processes share a machine.
torch::Device training_device(const std::string& name, const ProcessGroupEnv& processes) {
    if (name == "cuda" && processes.world_size > 1) return torch::Device(torch::kCUDA, static_cast<c10::DeviceIndex>(processes.local_rank));
    return torch::Device(name);
}

// Slots of the values that ride along with the gradients' all-reduce.
enum Rider : int64_t { kSimple, kPos, kVel, kFoot, kAcc, kTotal, kStop };

}  // namespace

void request_training_stop() { g_stop_requested = true; }

double ema_decay_at(double max_decay, int64_t step) {
    return std::min(max_decay, (1.0 + static_cast<double>(step)) / (10.0 + static_cast<double>(step)));
}

TrainProgress train_mdm(const TrainConfig& c, bool resume, const std::string& init_from, int64_t stop_after) {
    // Refused before anything waits for the other ranks.
    const BatchShare share = batch_share(c.batch, c.processes.rank, c.processes.world_size);
    const bool several = c.processes.world_size > 1;
    if (c.threads > 0) set_torch_threads(c.threads);
    Hml3dDataset data(c.dataset, c.split);
    if (data.clips().empty()) throw Error(c.dataset, c.split, "at least one usable clip (40 to 199 frames with a caption)");
    data.seed(c.seed);
    const WordVectors vocab = WordVectors::load(c.vocab);
    torch::manual_seed(c.seed);
    MdmConfig mc = c.mdm;
    mc.text_dim = c.text.out_dim;
    mc.mask_frames = true;
    const torch::Device device = training_device(c.device, c.processes);
    Training tr{Mdm(mc), GloveTextEncoder(vocab, c.text), nullptr, {}, noise_generator(device, c.seed, several), std::mt19937_64(c.seed + 1), 0};
    if (!init_from.empty()) {
        load_state_dict(*tr.mdm, init_from + "/weights.safetensors");
        load_state_dict(*tr.text, init_from + "/text_encoder.safetensors");
    }
    tr.mdm->to(device);
    tr.text->to(device);
    const DataParallel group(c.processes, device);
    group.broadcast_from_main(tr.parameters());  // the same seed already gave the same weights: this makes sure
    tr.optimiser = std::make_unique<torch::optim::AdamW>(tr.parameters(), torch::optim::AdamWOptions(c.learning_rate).weight_decay(c.weight_decay));
    if (c.ema_decay > 0)
        for (const torch::Tensor& p : tr.parameters()) tr.ema.push_back(p.detach().clone());
    if (group.is_main()) fs::create_directories(c.out);
    const std::string checkpoint = c.out + "/checkpoint.pt";
    if (resume) {
        if (!fs::exists(checkpoint)) throw Error(checkpoint, "file", "a checkpoint to resume from");
        load_checkpoint(tr, data, checkpoint, device);
    }
    if (several) seed_rank_dropout(device, c.seed, group.rank(), tr.step);
    const GaussianDiffusion diffusion(cosine_schedule(c.diffusion_steps));
    const torch::Tensor mean = torch::from_blob(const_cast<double*>(data.stats().mean.data()), {263}, torch::kFloat64).to(device, torch::kFloat32);
    const torch::Tensor std = torch::from_blob(const_cast<double*>(data.stats().std.data()), {263}, torch::kFloat64).to(device, torch::kFloat32);
    const torch::TensorOptions draws_on = torch::TensorOptions().device(several ? torch::Device(torch::kCPU) : device);
    std::string metrics;
    TrainProgress progress;
    const auto start = std::chrono::steady_clock::now();
    const int64_t first = tr.step, last = stop_after > 0 ? std::min(c.steps, tr.step + stop_after) : c.steps;
    std::bernoulli_distribution drop(c.cond_dropout);
    g_stop_requested = false;
    bool stop = false;
    while (tr.step < last && !stop) {
        // The global batch and all its draws, on every rank; this rank keeps samples [share.begin, + share.size).
        const Batch b = data.next_batch(c.batch);
        std::vector<std::string> captions = b.captions;
        for (std::string& caption : captions)
            if (drop(tr.dropout_rng)) caption.clear();
        const torch::Tensor t_all = torch::randint(c.diffusion_steps, {b.size}, tr.generator, draws_on.dtype(torch::kInt64));
        const torch::Tensor noise_all = torch::randn({b.size, b.channels, 1, b.frames}, tr.generator, draws_on);
        const int64_t lo = share.begin, n = share.size;
        const float* features = b.features.data() + static_cast<size_t>(lo) * static_cast<size_t>(b.frames * b.channels);
        const torch::Tensor x0 = torch::from_blob(const_cast<float*>(features), {n, b.frames, b.channels}, torch::kFloat32).to(device);
        const torch::Tensor lengths = torch::tensor(std::vector<int64_t>(b.lengths.begin() + lo, b.lengths.begin() + lo + n)).to(device);
        const std::vector<std::string> my_captions(captions.begin() + lo, captions.begin() + lo + n);
        const torch::Tensor t = t_all.slice(0, lo, lo + n).to(device);
        const torch::Tensor x0_mdm = x0.permute({0, 2, 1}).unsqueeze(2);  // [n, 263, 1, F]
        const torch::Tensor x_t = diffusion.q_sample(x0_mdm, t, noise_all.slice(0, lo, lo + n).to(device));
        const torch::Tensor x0_hat = tr.mdm->forward(x_t, t, tr.text->encode(my_captions), false, lengths).squeeze(2).permute({0, 2, 1});
        // Every term is a mean over the share of per-sample means (each normalised by its own valid frames,
        // losses.hpp), so the ranks' mean of equal shares is the global batch's mean: no normaliser to share.
        const LossTerms terms = mdm_loss_terms(x0, x0_hat, lengths, mean, std, c);
        tr.optimiser->zero_grad();
        terms.total.backward();
        const torch::Tensor stop_flag = torch::full({1}, g_stop_requested ? 1.0f : 0.0f, x0.options());
        const torch::Tensor riders =
            group.average_gradients(tr.parameters(), torch::cat({torch::stack({terms.simple, terms.pos, terms.vel, terms.foot, terms.acc, terms.total})
                                                                    .detach().to(torch::kFloat32), stop_flag}))
                .to(torch::kCPU, torch::kFloat64);
        const auto r = riders.accessor<double, 1>();
        stop = r[kStop] > 0;  // any rank's request stops all of them after the same step
        tr.optimiser->step();
        if (!tr.ema.empty()) {
            torch::NoGradGuard no_grad;
            const std::vector<torch::Tensor> params = tr.parameters();
            const double decay = ema_decay_at(c.ema_decay, tr.step);
            for (size_t i = 0; i < params.size(); ++i) tr.ema[i].mul_(decay).add_(params[i].detach(), 1 - decay);
        }
        ++tr.step;
        progress.loss = r[kTotal];
        if (!group.is_main()) continue;
        if (tr.step % c.log_every == 0 || tr.step == last || stop) {
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const double rate = static_cast<double>(tr.step - first) / std::max(seconds, 1e-9);
            const nlohmann::json line = {{"step", tr.step}, {"loss", progress.loss}, {"l_simple", r[kSimple]}, {"l_pos", r[kPos]},
                                         {"l_vel", r[kVel]}, {"l_foot", r[kFoot]}, {"l_acc", r[kAcc]}, {"steps_per_s", rate}};
            metrics += line.dump() + "\n";
            std::fprintf(stderr, "step %lld/%lld loss %.4f (simple %.4f acc %.4f) %.2f steps/s ETA %.0f s\n", static_cast<long long>(tr.step),
                         static_cast<long long>(c.steps), progress.loss, r[kSimple], r[kAcc], rate,
                         static_cast<double>(c.steps - tr.step) / std::max(rate, 1e-9));
        }
        if (tr.step % c.save_every == 0 || tr.step == last || stop) {
            std::string previous;
            if (fs::exists(c.out + "/metrics.jsonl")) previous = read_file_text(c.out + "/metrics.jsonl");
            write_file_atomic(c.out + "/metrics.jsonl", previous + metrics);
            metrics.clear();
            save_checkpoint(tr, data, checkpoint);
            write_model(tr, c, data);
        }
    }
    group.barrier();  // the other ranks return once rank 0's files are written
    progress.step = tr.step;
    return progress;
}

}  // namespace t2imu
