// t2imu synth: the main job, prompts -> motions -> bodies -> virtual sensors -> an IMU dataset.
#include <cstdio>
#include <filesystem>
#include <string_view>

#include "cli/command.hpp"
#include "cli/sampler_option.hpp"
#include "cli/usage.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "core/parse.hpp"
#include "pipeline/synth.hpp"
#include "pipeline/synth_keys.hpp"

namespace t2imu::cli {

namespace {

// Relative to the working directory, like models/default: the quick start runs from the repository root.
const char* const kDefaultActivityReference = "models/motion-activity.csv";

struct SynthArgs {
    SynthOptions options;
    std::string shard = "1/1";
};

// "I/N", 1-based on the command line.
void parse_shard(const std::string& text, SynthOptions& o) {
    const auto [i, n] = t2imu::parse_shard(text, "--shard", "shard");
    o.shard = i - 1;
    o.shards = n;
}

void run(SynthArgs a) {
    SynthOptions& o = a.options;
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

// Adds one shared setting (pipeline/synth_keys.hpp) as a flag of `cmd`.
struct AddSynthFlag {
    CLI::App& cmd;
    void operator()(SynthKey<bool> k) const {
        if (std::string_view(k.flag).substr(0, 5) == "--no-")
            cmd.add_flag_function(
                k.flag, [&field = k.field](int64_t) { field = false; }, k.help);
        else
            cmd.add_flag(k.flag, k.field, k.help);
    }
    void operator()(SynthKey<Sampler> k) const { add_sampler_option(cmd, k.field, k.help); }
    void operator()(SynthKey<std::optional<double>> k) const {
        cmd.add_option_function<double>(
            k.flag, [&field = k.field](double w) { field = w; }, k.help);
    }
    template <class T>
    void operator()(SynthKey<T> k) const {
        cmd.add_option(k.flag, k.field, k.help);
    }
};

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    auto* cmd =
        root.add_subcommand("synth", "the main job: prompts -> motions -> bodies -> virtual sensors -> an IMU dataset");
    auto& a = option_values<SynthArgs>();
    SynthOptions& o = a.options;
    cmd->add_option("--prompts", o.prompts, "prompt set: activity<TAB>prompt per line (prompts/*.tsv)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--model", o.model,
                    "model folder, retrieval:DATASET, or hybrid:MODEL,DATASET,STRENGTH (a retrieved clip noised to "
                    "STRENGTH in (0, 1] and finished by the model)");
    cmd->add_option("--sensors", o.sensors, "placement sets (as imu synth --sensors)");
    o.activity_reference = kDefaultActivityReference;
    visit_synth_keys(o, AddSynthFlag{*cmd});
    cmd->add_flag("--require-coverage", o.require_coverage,
                  "refuse a prompt the source's training captions do not cover: an unknown activity or an attribute "
                  "none names (default: warn)");
    cmd->add_option("--shard", a.shard, "I/N: run the I-th of N contiguous blocks of jobs (default 1/1)");
    cmd->add_option("--out", o.out, "output folder (resumed when it holds the same synthesis)")->required();
    cmd->callback([&a] { run(a); });
});

}  // namespace t2imu::cli
