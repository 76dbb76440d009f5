// t2imu synth: the main job, prompts -> motions -> bodies -> virtual sensors -> an IMU dataset.
#include <cstdio>
#include <filesystem>

#include "cli/command.hpp"
#include "cli/sampler_option.hpp"
#include "cli/usage.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "core/parse.hpp"
#include "imu/dataset_profile.hpp"
#include "imu/realism.hpp"
#include "pipeline/synth.hpp"

namespace t2imu::cli {

namespace {

// Relative to the working directory, like models/default: the quick start runs from the repository root.
const char* const kDefaultActivityReference = "models/motion-activity.csv";

struct SynthArgs {
    SynthOptions options;
    std::string shard = "1/1";
    bool no_filter = false;
};

// "I/N", 1-based on the command line.
void parse_shard(const std::string& text, SynthOptions& o) {
    const auto [i, n] = t2imu::parse_shard(text, "--shard", "shard");
    o.shard = i - 1;
    o.shards = n;
}

void run(SynthArgs a) {
    SynthOptions& o = a.options;
    o.filter = !a.no_filter;
    const bool no_reference =
        o.activity_reference == kDefaultActivityReference && !std::filesystem::exists(o.activity_reference);
    if (no_reference) o.activity_reference.clear();
    o.device = global_options().device;
    o.threads = worker_threads();
    SynthPlan plan;
    check_usage([&] {
        parse_shard(a.shard, o);
        check_output(o.out, "--out", OutputKind::folder, {o.prompts, o.activity_reference});
        plan = plan_synth(o);
    });
    if (no_reference)
        std::fprintf(stderr, "synth: no %s here: motions are not checked for their prompt's activity\n",
                     kDefaultActivityReference);
    const SynthReport r = run_synth(plan);
    const SynthRunTiming& t = r.this_run;
    std::printf(
        "%s: %d of %d jobs done (%d motions kept, %d of them below the activity agreement, %d dropped, %d "
        "regenerated), %d recordings; this run: %d jobs in %.1f s "
        "(motions %.1f s, quality %.1f s, bodies+IMU+write %.1f s)\n",
        o.out.c_str(), r.jobs_done, r.jobs, r.motions_kept, r.motions_kept_below_activity_agreement, r.motions_dropped,
        r.jobs_regenerated, r.recordings, t.jobs_run, t.total_s, t.motion_generation_s, t.quality_scoring_s,
        t.bodies_imu_write_s);
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    auto* cmd =
        root.add_subcommand("synth", "the main job: prompts -> motions -> bodies -> virtual sensors -> an IMU dataset");
    auto& a = option_values<SynthArgs>();
    SynthOptions& o = a.options;
    cmd->add_option("--prompts", o.prompts, "prompt set: activity<TAB>prompt per line (prompts/*.tsv)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--samples-per-prompt", o.samples_per_prompt, "motions per prompt");
    cmd->add_option("--model", o.model,
                    "model folder, retrieval:DATASET, or hybrid:MODEL,DATASET,STRENGTH (a retrieved clip noised to "
                    "STRENGTH in (0, 1] and finished by the model)");
    cmd->add_option("--vocab", o.vocab,
                    "GloVe vocabulary for retrieval (default $T2IMU_VOCAB or cache/text/glove-100k.safetensors)");
    add_sampler_option(*cmd, o.sampling.sampler, "dpmpp (default), ddim or ddpm");
    cmd->add_option("--steps", o.sampling.steps, "denoiser evaluations for ddim/dpmpp");
    cmd->add_option("--guidance", o.sampling.guidance, "classifier-free guidance scale");
    cmd->add_option_function<double>(
        "--caption-anchor", [&a](double w) { a.options.sampling.caption_anchor = w; },
        "weight 0..1 of the training captions nearest the prompt in its text feature (default: the model folder's; 0 = "
        "the prompt alone)");
    cmd->add_option("--seconds", o.seconds, "motion length, s (at most 9.8)");
    cmd->add_option("--seed", o.sampling.seed, "seed of job 0; job k draws from seed + k");
    cmd->add_option("--batch", o.sampling.batch,
                    "motions per sampling batch (fixed groups of jobs; another size changes motions by float rounding "
                    "only; default 16)");
    cmd->add_option("--bodies", o.bodies, "body shapes (as imu synth --body)");
    cmd->add_option("--sensors", o.sensors, "placement sets (as imu synth --sensors)");
    cmd->add_option("--rate", o.rate_hz, "sensor sample rate, Hz");
    cmd->add_option("--realism", o.realism, realism_help());
    cmd->add_flag(
        "--no-capture-rate{false}", o.capture_rate,
        "the sensors see a retrieved captured clip at 20 fps, not at its capture rate (the dataset's capture_joints/)");
    cmd->add_flag("--no-filter", a.no_filter, "keep every motion (the quality filter is on by default)");
    o.activity_reference = kDefaultActivityReference;
    cmd->add_option(
        "--activity-reference", o.activity_reference,
        "captured clips the activity check compares with (default models/motion-activity.csv; \"\" = no check)");
    cmd->add_option("--min-activity-agreement", o.min_activity_agreement, "activity check threshold, 0..1");
    cmd->add_flag("--drop-activity-failures", o.drop_activity_failures,
                  "drop a motion whose every draw fails the activity check (default: keep its best-agreeing draw)");
    cmd->add_flag("--require-coverage", o.require_coverage,
                  "refuse a prompt the source's training captions do not cover: an unknown activity or an attribute "
                  "none names (default: warn)");
    cmd->add_option("--retries", o.max_retries, "draws after the first for a motion the filter rejects");
    cmd->add_option("--shard", a.shard, "I/N: run the I-th of N contiguous blocks of jobs (default 1/1)");
    cmd->add_option("--out", o.out, "output folder (resumed when it holds the same synthesis)")->required();
    cmd->callback([&a] { run(a); });
});

}  // namespace t2imu::cli
