// Training and fine-tuning MDM with the default text encoder on a HumanML3D-layout dataset, with the paper's
// loss: L = L_simple + lambda_pos L_pos + lambda_vel L_vel + lambda_foot L_foot + lambda_acc L_acc.
//
// Every step: a batch (MDM's crop and caption rules, hml3d_dataset.hpp), t uniform in [0, T), x_t = q_sample,
// the captions reworded when [augment] asks (caption_augment.hpp) and encoded (each replaced by the empty
// caption with probability cond_dropout, which encodes to MDM's zero text feature: classifier-free guidance), x0_hat =
// MDM(x_t, t, text), then, each masked to valid frames: L_simple = MSE(x0_hat, x0) on normalised features; L_pos = MSE
// of joint positions (metres) from a differentiable recover_from_ric of the de-normalised features; L_vel = MDM's
// velocity term on the features; L_foot = squared predicted velocity of the four foot joints where the ground truth's
// contact flag is 1; L_acc = the paper's second-difference loss, on the normalised features or on joint positions
// (acc_space). AdamW; optional EMA of the weights. Checkpoints (model, optimiser, EMA, step, both random generators'
// states, the dataset's draw state) are written atomically every save_every steps and at the end, so a run
// resumed after a kill continues on the same trajectory. Metrics go to metrics.jsonl, one line per log step.
//
// Over several processes (config.processes, distributed.hpp) every rank draws the whole global batch with the
// same generators (data order, crops, captions and their dropout, t, noise: all from the global seed), keeps
// its equal share of the samples, and the gradients are averaged before the step; the ranks' shares together
// are exactly the one-process batch, so N processes of batch/N train the same weights as one process of batch
// (up to float summation order). Not shared: the model's own dropout masks, drawn per rank from a stream seeded
// with the seed, the rank and the starting step (a resumed multi-process run with dropout > 0 therefore draws
// other masks than an uninterrupted one). Rank 0 alone writes the model, checkpoints, metrics and progress;
// every rank resumes from config.out/checkpoint.pt, so the folder must be one they all see.
#pragma once
#include <cstdint>
#include <string>

#include "diffusion/mdm.hpp"
#include "nn/distributed.hpp"
#include "text/caption_augment.hpp"
#include "text/nn/glove_text_encoder.hpp"

namespace t2imu {

struct TrainConfig {
    std::string dataset, out, vocab, split = "train";
    MdmConfig mdm;  // latent_dim, ff_size, num_layers, num_heads, dropout (text_dim = text.out_dim)
    GloveEncoderConfig text;
    int diffusion_steps = 1000;
    int batch = 32;
    int64_t steps = 10000;
    double learning_rate = 1e-4, weight_decay = 0.0, cond_dropout = 0.1, ema_decay = 0.0;
    double lambda_pos = 0, lambda_vel = 0, lambda_foot = 0, lambda_acc = 0;
    std::string acc_space = "features";  // or "joints"
    // With acc_space joints: the SMPL-22 joints L_acc compares (motion/skeleton.hpp names); empty: all of them.
    std::vector<std::string> acc_joints;
    CaptionAugmentOptions augment;  // [augment]: the training captions reworded (text/caption_augment.hpp)
    int64_t save_every = 1000, log_every = 50;
    std::string precision =
        "fp32";  // or "bf16": the forward's products in bfloat16, weights and losses fp32 (nn/autocast.hpp)
    uint64_t seed = 0;
    int threads = 0;
    std::string device =
        "cpu";  // a torch device: cpu, cuda, cuda:1 (not in the TOML: where to train is not what to train)
    ProcessGroupEnv processes;  // data-parallel ranks (torchrun's variables; not in the TOML either)
    double max_minutes = 0;     // > 0: stop after the step that reaches this wall time, saved (a leased GPU's budget)
    bool profile = false;       // on a GPU, wait for each part's kernels so the profile is exact (slower)

    // Throws Error naming `path` and the dotted field ("train.learning_rate") for a missing or out-of-range
    // value: sizes from 1, heads dividing their width, rates and dropouts in [0, 1), lambdas from 0.
    void validate(const std::string& path) const;
};

// TOML: [data] dataset, vocab, split; [model] latent_dim, ff_size, num_layers, num_heads, dropout;
// [text] model_dim, layers, heads, ff_size, dropout; [diffusion] steps; [train] batch, steps, learning_rate,
// weight_decay, cond_dropout, ema_decay, seed, save_every, log_every, precision; [loss] lambda_pos, lambda_vel,
// lambda_foot, lambda_acc, acc_space, acc_joints; [augment] swap, dropout, neighbours, min_similarity, search_words;
// `out` at the top level (the model folder). Read strictly (core/toml_section.hpp): unknown keys and wrong types are
// refused by name; then validate().
TrainConfig read_train_config(const std::string& path);

// The EMA decay after `step` updates of this run: min(max_decay, (1 + step) / (10 + step)). Without the
// warm-up a plain 0.9999 keeps 0.9999^n of the starting weights: 0.3 of the random initialisation after
// 12,000 steps, which blurs the model's predictions (our first shipped model had exactly this fault).
double ema_decay_at(double max_decay, int64_t step);

// Seconds spent in each part of a training step, summed over the profiled steps: every step of one train_mdm
// call but its first (which builds kernels, oneDNN primitives and allocator caches).
//   data       draw and crop the batch (hml3d_dataset.hpp), reword captions, draw t and noise, copy to the
//              device, q_sample
//   text       tokenise and encode the captions
//   forward    MDM's forward and the loss terms
//   backward   backward and the gradients' all-reduce (with the loss values riding along)
//   optimiser  AdamW's step;  ema  the weights' moving average;  log  metrics, checkpoint and model writes
struct StepProfile {
    double data = 0, text = 0, forward = 0, backward = 0, optimiser = 0, ema = 0, log = 0;
    int64_t steps = 0;
    double total() const { return data + text + forward + backward + optimiser + ema + log; }
};

struct TrainProgress {
    int64_t step = 0;
    int64_t steps_run = 0;       // by this call: 0 when a resumed run was already at train.steps
    double loss = 0;             // the last logged total
    bool stopped_early = false;  // by a signal or max_minutes, before its last step
    StepProfile profile;
};

// Trains into config.out (model.json, weights.safetensors, Mean.npy, Std.npy, checkpoint.pt, metrics.jsonl).
// resume: continue from config.out/checkpoint.pt. init_from: start from another model folder's weights
// (fine-tuning), with a fresh optimiser. `stop_after` > 0 ends after that many steps of this call (tests).
TrainProgress train_mdm(const TrainConfig& config, bool resume, const std::string& init_from = "",
                        int64_t stop_after = 0);

// Asks a running train_mdm to finish its step, write its checkpoint and model, and return: safe to call from
// a signal handler (the CLI calls it on SIGINT and SIGTERM, so `timeout -s INT` ends a run cleanly).
void request_training_stop();

// The per-step loss terms for one batch, exposed for tests: every term averaged over the batch.
struct LossTerms {
    torch::Tensor simple, pos, vel, foot, acc, total;
};
LossTerms mdm_loss_terms(const torch::Tensor& x0, const torch::Tensor& x0_hat, const torch::Tensor& lengths,
                         const torch::Tensor& mean, const torch::Tensor& std, const TrainConfig& config);

}  // namespace t2imu
