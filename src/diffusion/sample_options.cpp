#include "diffusion/sample_options.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/number_text.hpp"

namespace t2imu {

const std::vector<std::string>& sampler_names() {
    static const std::vector<std::string> names = {"ddpm", "ddim", "dpmpp"};
    return names;
}

const std::string& sampler_name(Sampler sampler) { return sampler_names()[static_cast<size_t>(sampler)]; }

Sampler parse_sampler(const std::string& name, const std::string& option) {
    const std::vector<std::string>& names = sampler_names();
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<Sampler>(i);
    throw Error(option, "sampler", "ddpm, ddim or dpmpp", name);
}

int denoiser_calls(Sampler sampler, int steps, int schedule_steps) {
    return sampler == Sampler::ddpm ? schedule_steps : steps;
}

void check_guidance_scale(double scale, const std::string& option) {
    if (!(scale >= 0 && scale <= kMaxGuidance))
        throw Error("sampling", option, "a scale from 0 to " + std::to_string(static_cast<int>(kMaxGuidance)),
                    std::to_string(scale));
}

int frames_for_seconds(double seconds, const std::string& option) {
    if (!(seconds * kSampleFps >= 3.5 && seconds * kSampleFps < kMaxSampleFrames + 0.5))
        throw Error(option, "seconds",
                    "0.2 to " + fixed_text(kMaxSampleFrames / kSampleFps, 1) + " s (4 to " +
                        std::to_string(kMaxSampleFrames) + " frames at 20 fps)",
                    std::to_string(seconds));
    return static_cast<int>(std::lround(seconds * kSampleFps));
}

void SampleOptions::validate() const {
    if (frames < 4 || frames > kMaxSampleFrames)
        throw Error("sampling", "--frames", "4 to " + std::to_string(kMaxSampleFrames) + " (20 fps)",
                    std::to_string(frames));
    // ddpm takes every step of the model's schedule and ignores `steps`.
    if (sampler != Sampler::ddpm && (steps < 1 || steps > 10000))
        throw Error("sampling", "--steps", "1 to 10000 denoiser evaluations", std::to_string(steps));
    // A huge scale turns every feature into inf or NaN (1e20 does in float32), found only much later (inverse
    // kinematics, the IMU stage). MDM samples at 2.5; past ~10 a scale extrapolates far beyond the data.
    check_guidance_scale(guidance, "--guidance");
    if (!(eta >= 0 && eta <= 1)) throw Error("sampling", "--eta", "0 to 1", std::to_string(eta));
    if (batch < 1) throw Error("sampling", "--batch", "at least 1", std::to_string(batch));
    if (!(strength > 0 && strength <= 1))
        throw Error("sampling", "--strength", "above 0 and at most 1", std::to_string(strength));
    if (caption_anchor && !(*caption_anchor >= 0 && *caption_anchor <= 1))
        throw Error("sampling", "--caption-anchor", "a weight from 0 to 1", std::to_string(*caption_anchor));
    if (!(height_crossover_hz == 0 || (height_crossover_hz > 0 && height_crossover_hz < kSampleFps / 2)))
        throw Error("sampling", "--height-crossover",
                    "0 (off) or above 0 and below " + std::to_string(static_cast<int>(kSampleFps / 2)) +
                        " Hz (half the frame rate)",
                    std::to_string(height_crossover_hz));
    for (const FeatureMatrix& m : start_motions)
        if (m.rows() != frames || m.cols() != 263)
            throw Error("sampling", "start motion", std::to_string(frames) + " x 263 features",
                        std::to_string(m.rows()) + " x " + std::to_string(m.cols()));
}

}  // namespace t2imu
