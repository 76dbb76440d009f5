// What a sampling run is asked for, without libtorch: the sampler by name and SampleOptions, so that the
// options of synth, the experiments and the sampler comparison (and the CLI files that bind them) compile
// without libtorch's headers. The samplers themselves are in samplers.hpp, sampling from a model in
// text_to_motion.hpp.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "motion/joint_sequence.hpp"

namespace t2imu {

// The samplers by the names options, configs and records use: "ddpm", "ddim", "dpmpp" (parsed here only).
enum class Sampler { ddpm, ddim, dpmpp };
const std::vector<std::string>& sampler_names();  // in the enum's order
const std::string& sampler_name(Sampler sampler);
Sampler parse_sampler(const std::string& name, const std::string& option = "--sampler");  // Error naming `option`
// Denoiser evaluations per motion: DDPM takes every step of the model's schedule, the others `steps`.
int denoiser_calls(Sampler sampler, int steps, int schedule_steps);

constexpr double kMaxGuidance = 100;  // classifier-free guidance scales accepted: [0, kMaxGuidance]
// Throws Error naming `option` unless 0 <= scale <= kMaxGuidance (NaN refused).
void check_guidance_scale(double scale, const std::string& option);
constexpr double kSampleFps = 20;      // HumanML3D's frame rate: every sampled motion is at 20 fps
constexpr int kMaxSampleFrames = 196;  // HumanML3D's longest clip (9.8 s): the longest motion a model samples

// A length in seconds as sampled frames (round(seconds * 20)); throws Error naming `option` unless the length is
// finite and gives 4 to 196 frames (0.2 to 9.8 s), the lengths SampleOptions accepts.
int frames_for_seconds(double seconds, const std::string& option);

struct SampleOptions {
    int frames = 120;                 // 20 fps; at most 196 (HumanML3D's longest)
    Sampler sampler = Sampler::ddpm;  // MDM's own: every step of the schedule (t2imu sample's default)
    int steps = 50;                   // denoiser evaluations for ddim and dpmpp (ddpm uses every step)
    double guidance = 2.5;
    double eta = 0.0;  // ddim only
    uint64_t seed = 0;
    std::vector<uint64_t> seeds;  // when given, one per prompt: sample i draws from seeds[i] instead of seed + i
    int batch = 16;
    // The hybrid (SDEdit, Meng et al. 2022): when given, one per prompt, motion i starts from start_motions[i]
    // (de-normalised features [frames, 263]) noised to step t_s = round(strength (T-1)) with its seed's noise,
    // x_ts = sqrt(abar_ts) x0 + sqrt(1 - abar_ts) eps, instead of from pure noise; strength 1 is pure noise
    // again, small strengths keep the start's motion. The few-step samplers spread min(steps, t_s + 1)
    // evaluations over t_s .. 0; DDPM takes t_s + 1 steps.
    std::vector<FeatureMatrix> start_motions;
    double strength = 1.0;
    // The caption anchor (text_to_motion.hpp): its weight w in [0, 1], unset = the model folder's own
    // (model.json caption_anchor.weight; 0 for a folder without one), 0 = the prompt alone; and, when given, one
    // canonical activity per prompt ("" = unknown) that chooses the captions the prompt is anchored to.
    std::optional<double> caption_anchor;
    std::vector<std::string> activities;
    // The joints' heights from the features' positions below this frequency and their velocities above it
    // (motion/velocity_fusion.hpp), Hz; 0 = the positions alone (recover_from_ric).
    double height_crossover_hz = 0;
    // A prompt asking for stairs both ways (activity "stairs") drawn as an ascent and a descent, each anchored to
    // its own direction's captions, joined at a stance (pipeline/motion_source.hpp); off: one draw of both.
    bool stairs_round_trips = false;

    // Throws Error naming the option (--frames, --steps, --guidance, --strength...) for a value out of range or not
    // finite.
    void validate() const;
};

}  // namespace t2imu
