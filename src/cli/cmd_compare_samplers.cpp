// t2imu compare-samplers: quality against steps (pipeline/sampler_comparison.hpp) — the same prompts and seeds
// through DDPM with every step and the few-step samplers, one CSV row per sampler.
#include <cmath>
#include <cstdio>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/csv.hpp"
#include "core/output_path.hpp"
#include "pipeline/sampler_comparison.hpp"

namespace t2imu::cli {

namespace {

struct CompareArgs {
    SamplerComparisonOptions options;
    std::string prompts, samplers = "ddpm,ddim:10,ddim:20,ddim:50,dpmpp:5,dpmpp:10,dpmpp:20", out;
    double seconds = 6;
};

void run(CompareArgs a) {
    SamplerComparisonOptions& o = a.options;
    std::vector<SamplerConfig> configs;
    check_usage([&] {
        o.frames = frames_for_seconds(a.seconds, "--seconds");
        o.validate();
        configs = parse_sampler_configs(a.samplers);
        check_output(a.out, "--out", OutputKind::file, {a.prompts, o.model, o.activity_reference, o.captured_dataset});
    });
    o.prompts = read_prompt_set(a.prompts);
    o.device = global_options().device;
    const CsvTable t = compare_samplers(o, configs);
    write_csv(a.out, t);
    std::printf("%-12s %6s %9s %12s %12s %10s %9s %9s\n", "sampler", "calls", "motion/s", "acc energy", "joint acc",
                "descr. d", "quality", "activity");
    for (size_t r = 0; r < t.rows.size(); ++r)
        std::printf("%-12s %6s %9.2f %6.3f (%.2f) %6.2f (%.2f) %10.3f %8.0f%% %8.0f%%\n", t.rows[r][0].c_str(),
                    t.rows[r][1].c_str(), t.number(r, 4), t.number(r, 5), t.number(r, 6), t.number(r, 7),
                    t.number(r, 8), t.number(r, 9), 100 * (1 - t.number(r, 10)), 100 * t.number(r, 11));
    std::printf(
        "(ratios to the first row in brackets; quality = share passing the filter; activity = share passing the "
        "activity check)\n%s\n",
        a.out.c_str());
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    auto* cmd = root.add_subcommand("compare-samplers",
                                    "quality against steps: the same prompts and seeds through several samplers, "
                                    "compared with the first (DDPM with every step)");
    auto& a = option_values<CompareArgs>();
    SamplerComparisonOptions& o = a.options;
    cmd->add_option("--model", o.model, "model folder")->required()->check(CLI::ExistingDirectory);
    cmd->add_option("--prompts", a.prompts, "prompt set: activity<TAB>prompt per line")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--samplers", a.samplers, "comma-separated: ddpm, ddim:K, dpmpp:K; the first is the reference");
    cmd->add_option("--samples-per-prompt", o.samples_per_prompt, "motions per prompt");
    cmd->add_option("--seconds", a.seconds, "motion length, s");
    cmd->add_option("--seed", o.seed, "seed of the first motion; motion i draws from seed + i in every sampler");
    cmd->add_option("--guidance", o.guidance, "classifier-free guidance scale");
    cmd->add_option("--batch", o.batch, "motions per denoiser batch");
    cmd->add_option("--activity-reference", o.activity_reference,
                    "activity check reference CSV (models/motion-activity.csv)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--captured", o.captured_dataset,
                    "HumanML3D-layout dataset: a last row with its captured clips' statistics")
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--captured-split", o.captured_split, "split of --captured");
    cmd->add_option("--out", a.out, "output CSV")->required();
    cmd->callback([&a] { run(a); });
});

}  // namespace t2imu::cli
