// The settings a synthesis takes from `t2imu synth`'s flags and from an experiment's [synth] section: one list, each
// with its TOML key, its flag and its help, walked by the CLI (cli/cmd_synth.cpp) and by the config reader
// (pipeline/experiment_config.cpp), so a setting cannot exist in one and not the other. What is checked is checked
// once, by plan_synth. The settings an experiment gives per row (prompts, model, sensors, out) are not in it.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "imu/realism.hpp"
#include "pipeline/synth.hpp"

namespace t2imu {

// One shared setting; `field` refers into the options being filled.
template <class T>
struct SynthKey {
    const char* key;   // in an experiment's [synth]
    const char* flag;  // of t2imu synth; a bool's "--no-x" turns off a setting that is on by default
    std::string help;
    T& field;
};

// Calls visit(SynthKey<T>) for each shared setting of `o`, in the order of synth's help.
template <class Visit>
void visit_synth_keys(SynthOptions& o, Visit&& visit) {
    SampleOptions& s = o.sampling;
    visit(SynthKey<int>{"samples_per_prompt", "--samples-per-prompt", "motions per prompt", o.samples_per_prompt});
    visit(SynthKey<std::string>{"vocab", "--vocab",
                                "GloVe vocabulary for retrieval (default $T2IMU_VOCAB or "
                                "cache/text/glove-100k.safetensors)",
                                o.vocab});
    visit(SynthKey<Sampler>{"sampler", "--sampler", "dpmpp (default), ddim or ddpm", s.sampler});
    visit(SynthKey<int>{"steps", "--steps", "denoiser evaluations for ddim/dpmpp", s.steps});
    visit(SynthKey<double>{"guidance", "--guidance", "classifier-free guidance scale", s.guidance});
    visit(SynthKey<std::optional<double>>{"caption_anchor", "--caption-anchor",
                                          "weight 0..1 of the training captions nearest the prompt in its text "
                                          "feature (default: the model folder's; 0 = the prompt alone)",
                                          s.caption_anchor});
    visit(SynthKey<double>{"height_crossover_hz", "--height-crossover",
                           "a model's joint heights from its features' positions below this frequency and their "
                           "velocities above it, Hz (0 = the positions alone)",
                           s.height_crossover_hz});
    visit(SynthKey<bool>{"stairs_round_trips", "--stairs-round-trips",
                         "a model draws a prompt asking for stairs up and down as an ascent and a descent joined at "
                         "a stance",
                         s.stairs_round_trips});
    visit(SynthKey<double>{"seconds", "--seconds", "motion length, s (at most 9.8)", o.seconds});
    visit(SynthKey<uint64_t>{"seed", "--seed", "seed of job 0; job k draws from seed + k", s.seed});
    visit(SynthKey<int>{"batch", "--batch",
                        "motions per sampling batch (fixed groups of jobs; another size changes motions by float "
                        "rounding only; default 16)",
                        s.batch});
    visit(SynthKey<std::string>{"bodies", "--bodies", "body shapes (as imu synth --body)", o.bodies});
    visit(SynthKey<double>{"rate_hz", "--rate", "sensor sample rate, Hz", o.rate_hz});
    visit(SynthKey<std::string>{"realism", "--realism", realism_help(), o.realism});
    visit(SynthKey<bool>{"capture_rate", "--no-capture-rate",
                         "the sensors see a retrieved captured clip at 20 fps, not at its capture rate (the dataset's "
                         "capture_joints/)",
                         o.capture_rate});
    visit(SynthKey<bool>{"filter", "--no-filter", "keep every motion (the quality filter is on by default)", o.filter});
    visit(SynthKey<std::string>{"activity_reference", "--activity-reference",
                                "captured clips the activity check compares with (default models/motion-activity.csv; "
                                "\"\" = no check)",
                                o.activity_reference});
    visit(SynthKey<double>{"min_activity_agreement", "--min-activity-agreement", "activity check threshold, 0..1",
                           o.min_activity_agreement});
    visit(SynthKey<bool>{"drop_activity_failures", "--drop-activity-failures",
                         "drop a motion whose every draw fails the activity check (default: keep its best-agreeing "
                         "draw)",
                         o.drop_activity_failures});
    visit(SynthKey<int>{"max_retries", "--retries", "draws after the first for a motion the filter rejects",
                        o.max_retries});
}

}  // namespace t2imu
