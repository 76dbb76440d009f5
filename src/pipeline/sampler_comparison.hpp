// Quality against steps: several samplers (DDPM with every step, DDIM and DPM-Solver++ 2M at K steps) draw
// the same prompts from the same seeds, and each is compared with the first, the reference (DDPM with all of
// the model's steps, as MDM samples). The paper names better numerical schemes than Euler steps as future work;
// this measures what fewer denoiser evaluations cost.
//
// Per sampler, over its N motions (20 fps):
//   seconds, motions_per_s      wall time of sample_motions on this machine
//   feature_acc_energy          mean over motions of 1/(F-2) sum_i ||x[i+1] - 2x[i] + x[i-1]||^2 on the
//                               normalised 263-d features: the quantity L_acc matches against captured motion
//   joint_acc_rms_m_s2          RMS over motions, frames and joints of the joints' second difference * fps^2
//   descriptor_distance         diagonal Fréchet distance between the motions' twelve descriptors
//                               (motion_descriptors.hpp) and the reference's: sum_d ((mu_d - mu_ref,d)^2 +
//                               (sd_d - sd_ref,d)^2) / sd_ref,d^2, so 0 = the same distribution, and a
//                               shift of one reference SD in one descriptor adds 1
//   quality_failure_rate        share failing any of the quality filter's scores (motion_quality.hpp)
//   activity_pass_rate          share of checkable motions whose activity agreement passes the activity
//                               check (needs a reference; NaN without one)
// Ratios to the reference row are written beside the acceleration figures. With a captured dataset, a last
// row holds the same statistics of its captured clips (a split of a HumanML3D-layout folder): the target.
#pragma once
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "diffusion/sample_options.hpp"
#include "text/prompt_set.hpp"

namespace t2imu {

struct SamplerConfig {
    Sampler sampler = Sampler::ddpm;
    int steps = 0;  // ignored for ddpm (every step of the model's schedule)
    std::string name() const;
};

// "ddpm,ddim:20,dpmpp:10" -> configs; throws Error on a malformed entry.
std::vector<SamplerConfig> parse_sampler_configs(const std::string& text);

struct SamplerComparisonOptions {
    std::string model;  // model folder
    std::vector<Prompt> prompts;
    int samples_per_prompt = 1;  // sample s of prompt p draws from seed + p * samples_per_prompt + s
    uint64_t seed = 0;
    int frames = 120;
    double guidance = 2.5;
    int batch = 16;
    std::string device = "cpu";
    std::string activity_reference;  // "" = no activity column
    double min_activity_agreement = 0.55;
    std::string captured_dataset;  // "" = no captured row
    std::string captured_split = "test";

    // Throws Error naming the option (--seconds, --guidance, --batch, --samples-per-prompt...) of a value out of
    // range or not finite; the prompts and files are checked where they are read.
    void validate() const;
};

// One row per config, the first being the reference; columns as above.
CsvTable compare_samplers(const SamplerComparisonOptions& options, const std::vector<SamplerConfig>& configs);

}  // namespace t2imu
