// t2imu sample: prompts -> motions (HumanML3D features and joints .npy) from a trained model folder.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/sampler_option.hpp"
#include "cli/usage.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "core/output_path.hpp"
#include "diffusion/lacc_evaluation.hpp"
#include "diffusion/text_to_motion.hpp"
#include "motion/activity_names.hpp"
#include "motion/humanml3d.hpp"
#include "motion/velocity_fusion.hpp"
#include "text/prompt_coverage.hpp"
#include "text/prompt_set.hpp"

namespace t2imu::cli {

namespace {

struct SampleArgs {
    std::string model, prompt, prompts, out;
    bool require_coverage = false;
    double seconds = 0;  // 0: not given (then frames, then SampleOptions' default length)
    int frames = 0;
    SampleOptions options;
};

void run(SampleArgs a) {
    check_usage([&] {
        if (a.prompt.empty() == a.prompts.empty())
            throw Error("sample", "prompt", "either --prompt TEXT or --prompts FILE");
        if (a.seconds != 0 && a.frames != 0) throw Error("sample", "length", "either --seconds or --frames");
        if (!a.prompt.empty()) check_prompt_text(a.prompt, "--prompt", "text");
        if (a.frames != 0) a.options.frames = a.frames;
        if (a.seconds != 0) a.options.frames = frames_for_seconds(a.seconds, "--seconds");
        a.options.validate();
        check_output(a.out, "--out", OutputKind::folder, {a.model, a.prompts});
    });
    const std::vector<Prompt> prompts =
        a.prompt.empty() ? read_prompt_set(a.prompts) : std::vector<Prompt>{{"", a.prompt}};
    std::unique_ptr<MotionModel> model = load_motion_model(a.model, global_options().device);
    const double anchor_weight = model->caption_anchor_weight(a.options.caption_anchor);
    std::vector<PromptCoverage> coverage;
    if (model->anchor.index)
        coverage = check_prompts_covered(*model->anchor.index, prompts, a.prompts.empty() ? "--prompt" : a.prompts,
                                         a.require_coverage);
    std::vector<std::string> texts;
    for (const Prompt& p : prompts) {
        texts.push_back(p.text);
        a.options.activities.push_back(activity_asked(p.activity, p.text));
    }
    const auto start = std::chrono::steady_clock::now();
    const std::vector<FeatureMatrix> motions = sample_motions(*model, texts, a.options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::json record = {{"model", std::filesystem::absolute(a.model).string()},
                             {"model_training", model->meta.value("training", nlohmann::json{})},
                             {"sampler", sampler_name(a.options.sampler)},
                             {"steps", denoiser_calls(a.options.sampler, a.options.steps, model->schedule.steps)},
                             {"guidance", a.options.guidance},
                             {"eta", a.options.eta},
                             {"caption_anchor", anchor_weight},
                             {"height_crossover_hz", a.options.height_crossover_hz},
                             {"frames", a.options.frames},
                             {"fps", 20},
                             {"seed", a.options.seed},
                             {"device", global_options().device},
                             {"sampling_seconds", seconds},
                             {"samples", nlohmann::json::array()}};
    char name[32];
    for (size_t i = 0; i < motions.size(); ++i) {
        std::snprintf(name, sizeof name, "%04zu", i);
        record["samples"].push_back({{"id", name},
                                     {"prompt", prompts[i].text},
                                     {"activity", prompts[i].activity},
                                     {"activity_asked", a.options.activities[i]},
                                     {"seed", a.options.seed + i}});
        if (!coverage.empty()) record["samples"].back()["coverage"] = coverage[i].summary();
    }
    // Serialised before the motions are written: samples.json is what says the folder is complete.
    const std::string samples_json = record.dump(2) + "\n";
    claim_output_folder(a.out);
    for (size_t i = 0; i < motions.size(); ++i) {
        std::snprintf(name, sizeof name, "%04zu", i);
        write_npy(a.out + "/" + name + "_features.npy", feature_matrix_to_array(motions[i]));
        write_npy(a.out + "/" + name + "_joints.npy",
                  joint_sequence_to_array(joints_from_features(motions[i], a.options.height_crossover_hz)));
    }
    write_file_atomic(a.out + "/samples.json", samples_json);
    std::printf("%s: %zu motions of %d frames (%s, guidance %g) in %.2f s on %s (%.2f motions/s)\n", a.out.c_str(),
                motions.size(), a.options.frames, sampler_name(a.options.sampler).c_str(), a.options.guidance, seconds,
                global_options().device.c_str(), static_cast<double>(motions.size()) / std::max(seconds, 1e-9));
}

}  // namespace

static void add_eval_lacc(CLI::App& root) {
    auto* cmd = root.add_subcommand(
        "eval-lacc", "per-sample L_acc of a model over a dataset split (id,caption,t,l_acc,l_simple CSV)");
    auto& model = option_values<std::string>();
    auto& dataset = option_values<std::string>();
    auto& split = option_values<std::string>("test");
    auto& out = option_values<std::string>();
    auto& seed = option_values<uint64_t>(0);
    cmd->add_option("--model", model, "model folder")->required()->check(CLI::ExistingDirectory);
    cmd->add_option("--dataset", dataset, "HumanML3D-layout dataset")->required()->check(CLI::ExistingDirectory);
    cmd->add_option("--split", split, "train, val, test or all");
    cmd->add_option("--seed", seed, "seed of the draws (use the same for the models you compare)");
    cmd->add_option("--out", out, "output CSV")->required();
    cmd->callback([&dataset, &model, &out, &seed, &split] {
        check_usage([&dataset, &model, &out, &seed, &split] {
            check_output(out, "--out", OutputKind::file, {model, dataset});
        });
        std::unique_ptr<MotionModel> m = load_motion_model(model, global_options().device);
        const CsvTable table = evaluate_lacc(*m, dataset, split, seed);
        write_csv(out, table);
        double mean = 0;
        for (size_t r = 0; r < table.rows.size(); ++r)
            mean += table.number(r, 3) / static_cast<double>(table.rows.size());
        std::printf("%s: %zu samples, mean L_acc %.6g\n", out.c_str(), table.rows.size(), mean);
    });
}

static CommandRegistrar registrar([](CLI::App& root) {
    add_eval_lacc(root);
    auto* cmd = root.add_subcommand("sample",
                                    "prompts -> motions (features and joints .npy + samples.json) from a model folder");
    auto& a = option_values<SampleArgs>();
    cmd->add_option("--model", a.model,
                    "model folder (t2imu train, or an official MDM checkpoint with CLIP: docs/mdm-checkpoint.md)")
        ->required()
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--prompt", a.prompt, "one prompt");
    cmd->add_option("--prompts", a.prompts, "prompts file: one per line, or activity<TAB>prompt");
    cmd->add_option("--seconds", a.seconds, "length in seconds (20 fps)");
    cmd->add_option("--frames", a.frames, "length in frames (at most 196; default 120)");
    add_sampler_option(*cmd, a.options.sampler, "ddpm (default), ddim or dpmpp");
    cmd->add_option("--steps", a.options.steps, "denoiser evaluations for ddim/dpmpp");
    cmd->add_option("--guidance", a.options.guidance, "classifier-free guidance scale");
    cmd->add_option_function<double>(
        "--caption-anchor", [&a](double w) { a.options.caption_anchor = w; },
        "weight 0..1 of the training captions nearest the prompt in its text feature (default: the model folder's; 0 = "
        "the prompt alone)");
    cmd->add_option("--height-crossover", a.options.height_crossover_hz,
                    "the joints' heights from the features' positions below this frequency and their velocities above "
                    "it, Hz (0 = the positions alone)");
    cmd->add_option("--eta", a.options.eta, "ddim noise (0 = deterministic)");
    cmd->add_option("--seed", a.options.seed, "seed of sample 0; sample i uses seed + i");
    cmd->add_flag("--require-coverage", a.require_coverage,
                  "refuse a prompt the model's training captions do not cover (default: warn)");
    cmd->add_option("--batch", a.options.batch, "prompts per batch (does not change the samples)");
    cmd->add_option("--out", a.out, "output folder")->required();
    cmd->callback([&a] { run(a); });
});

}  // namespace t2imu::cli
