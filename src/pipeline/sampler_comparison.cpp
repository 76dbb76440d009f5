#include "pipeline/sampler_comparison.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "core/error.hpp"
#include "core/number_text.hpp"
#include "core/parse.hpp"
#include "data/hml3d_dataset.hpp"
#include "diffusion/text_to_motion.hpp"
#include "motion/humanml3d.hpp"
#include "motion/motion_activity.hpp"
#include "motion/motion_descriptors.hpp"
#include "motion/motion_quality.hpp"

namespace t2imu {

std::string SamplerConfig::name() const {
    return sampler == Sampler::ddpm ? sampler_name(sampler) : sampler_name(sampler) + ":" + std::to_string(steps);
}

std::vector<SamplerConfig> parse_sampler_configs(const std::string& text) {
    std::vector<SamplerConfig> out;
    for (const std::string& item : split_list(text)) {
        SamplerConfig c;
        const size_t colon = item.find(':');
        c.sampler = parse_sampler(item.substr(0, colon), "--samplers");
        if (colon != std::string::npos) {
            const std::optional<long long> steps = parse_integer(item.substr(colon + 1));
            if (!steps || *steps < 2 || *steps > 10000)
                throw Error("--samplers", "entry", "NAME:STEPS with STEPS from 2 to 10000", item);
            c.steps = static_cast<int>(*steps);
        }
        const bool ddpm = c.sampler == Sampler::ddpm;
        if (!(ddpm && colon == std::string::npos) && !(!ddpm && c.steps >= 2))
            throw Error("--samplers", "entry", "ddpm, ddim:K or dpmpp:K", item);
        out.push_back(c);
    }
    if (out.empty()) throw Error("--samplers", "list", "at least one sampler", text);
    return out;
}

namespace {

// What the table needs of one sampler's motions.
struct SamplerMotions {
    double seconds = 0;
    std::vector<double> feature_acc_energy, joint_acc_sq;  // per motion; per motion mean of squares
    std::vector<MotionDescriptors> descriptors;
    int quality_failures = 0, activity_checked = 0, activity_passed = 0;
};

double mean_second_difference_energy(const FeatureMatrix& x) {
    double s = 0;
    for (Eigen::Index i = 1; i + 1 < x.rows(); ++i) s += (x.row(i + 1) - 2 * x.row(i) + x.row(i - 1)).squaredNorm();
    return x.rows() > 2 ? s / static_cast<double>(x.rows() - 2) : 0.0;
}

double mean_joint_acceleration_squared(const JointSequence& m) {
    double s = 0;
    const double fps2 = m.fps * m.fps;
    for (int f = 1; f + 1 < m.num_frames; ++f)
        for (int j = 0; j < m.num_joints; ++j)
            s += ((m.at(f + 1, j) - 2 * m.at(f, j) + m.at(f - 1, j)) * fps2).squaredNorm();
    return s / static_cast<double>((m.num_frames - 2) * m.num_joints);
}

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
}

double diagonal_frechet(const std::vector<MotionDescriptors>& a, const std::vector<MotionDescriptors>& reference) {
    const DescriptorMoments m = descriptor_moments(a), r = descriptor_moments(reference);
    const MotionDescriptors &mu = m.mean, &sd = m.sd, &mu_ref = r.mean, &sd_ref = r.sd;
    double s = 0;
    for (size_t i = 0; i < kNumMotionDescriptors; ++i) {
        if (sd_ref[i] <= 0) continue;  // constant over the reference: no scale to measure a shift in
        s += ((mu[i] - mu_ref[i]) * (mu[i] - mu_ref[i]) + (sd[i] - sd_ref[i]) * (sd[i] - sd_ref[i])) /
             (sd_ref[i] * sd_ref[i]);
    }
    return s;
}

// The statistics of motions (de-normalised features); `expected[i]` is motion i's activity class ("" = unchecked).
SamplerMotions measure(const std::vector<FeatureMatrix>& motions, const FeatureStats& stats,
                       const std::vector<std::string>& expected, const MotionActivityClassifier* classifier,
                       double min_agreement) {
    SamplerMotions out;
    const MotionQualityThresholds limits = default_quality_thresholds();
    for (size_t i = 0; i < motions.size(); ++i) {
        const JointSequence joints = recover_from_ric(motions[i]);
        out.feature_acc_energy.push_back(mean_second_difference_energy(normalize_features(motions[i], stats)));
        out.joint_acc_sq.push_back(mean_joint_acceleration_squared(joints));
        out.descriptors.push_back(describe_motion(joints));
        out.quality_failures += !quality_failures(score_motion(joints), limits).empty();
        if (classifier && !expected[i].empty()) {
            ++out.activity_checked;
            out.activity_passed += classifier->classify(out.descriptors.back()).agreement(expected[i]) >= min_agreement;
        }
    }
    return out;
}

SamplerMotions draw(MotionModel& model, const SamplerComparisonOptions& o, const SamplerConfig& c,
                    const MotionActivityClassifier* classifier) {
    SampleOptions s;
    s.frames = o.frames;
    s.sampler = c.sampler;
    s.steps = c.steps;
    s.guidance = o.guidance;
    s.batch = o.batch;
    std::vector<std::string> texts, expected;
    for (size_t p = 0; p < o.prompts.size(); ++p)
        for (int k = 0; k < o.samples_per_prompt; ++k) {
            texts.push_back(o.prompts[p].text);
            expected.push_back(classifier ? reference_activity(o.prompts[p].activity, classifier->classes()) : "");
            s.seeds.push_back(o.seed + p * static_cast<uint64_t>(o.samples_per_prompt) + static_cast<uint64_t>(k));
        }
    const auto start = std::chrono::steady_clock::now();
    const std::vector<FeatureMatrix> motions = sample_motions(model, texts, s);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    SamplerMotions out = measure(motions, model.stats, expected, classifier, o.min_activity_agreement);
    out.seconds = seconds;
    return out;
}

// The captured clips of a dataset split (at least 3 frames), as the target the samplers are measured against.
SamplerMotions captured(const std::string& dataset, const std::string& split, const FeatureStats& stats) {
    std::vector<FeatureMatrix> motions;
    const Hml3dDataset clips(dataset, split);  // named: the clips live as long as it
    for (const MotionClip& c : clips.clips())
        if (c.features.rows() >= 3) motions.push_back(c.features);
    if (motions.empty()) throw Error(dataset, split, "captured clips of at least 3 frames");
    SamplerMotions out = measure(motions, stats, std::vector<std::string>(motions.size()), nullptr, 0);
    out.seconds = NAN;
    return out;
}

std::string number(double v) { return general_text(v, 6); }

}  // namespace

void SamplerComparisonOptions::validate() const {
    if (samples_per_prompt < 1 || samples_per_prompt > 1000)
        throw Error("sampler comparison", "--samples-per-prompt", "1 to 1000", std::to_string(samples_per_prompt));
    if (!(min_activity_agreement >= 0 && min_activity_agreement <= 1))
        throw Error("sampler comparison", "--min-activity-agreement", "0 to 1", std::to_string(min_activity_agreement));
    SampleOptions s;
    s.frames = frames;
    s.guidance = guidance;
    s.batch = batch;
    s.validate();
}

CsvTable compare_samplers(const SamplerComparisonOptions& o, const std::vector<SamplerConfig>& configs) {
    if (configs.empty() || o.prompts.empty() || o.samples_per_prompt < 1)
        throw Error("sampler comparison", "input", "samplers and prompts");
    std::unique_ptr<MotionModel> model = load_motion_model(o.model, o.device);
    std::optional<MotionActivityClassifier> classifier;
    if (!o.activity_reference.empty()) classifier = MotionActivityClassifier::load(o.activity_reference);
    CsvTable t;
    t.header = {"sampler",
                "denoiser_calls",
                "motions",
                "seconds",
                "motions_per_s",
                "feature_acc_energy",
                "feature_acc_energy_ratio",
                "joint_acc_rms_m_s2",
                "joint_acc_rms_ratio",
                "descriptor_distance",
                "quality_failure_rate",
                "activity_pass_rate"};
    std::optional<SamplerMotions> reference;
    const auto add_row = [&](const std::string& name, const std::string& calls, const SamplerMotions& m) {
        if (!reference) reference = m;
        const double n = static_cast<double>(m.descriptors.size());
        const double energy = mean(m.feature_acc_energy), rms = std::sqrt(mean(m.joint_acc_sq));
        t.rows.push_back(
            {name, calls, std::to_string(m.descriptors.size()), number(m.seconds), number(n / m.seconds),
             number(energy), number(energy / mean(reference->feature_acc_energy)), number(rms),
             number(rms / std::sqrt(mean(reference->joint_acc_sq))),
             number(diagonal_frechet(m.descriptors, reference->descriptors)), number(m.quality_failures / n),
             number(m.activity_checked > 0 ? static_cast<double>(m.activity_passed) / m.activity_checked : NAN)});
    };
    for (const SamplerConfig& c : configs)
        add_row(c.name(), std::to_string(denoiser_calls(c.sampler, c.steps, model->schedule.steps)),
                draw(*model, o, c, classifier ? &*classifier : nullptr));
    if (!o.captured_dataset.empty())
        add_row("captured:" + o.captured_split, "", captured(o.captured_dataset, o.captured_split, model->stats));
    return t;
}

}  // namespace t2imu
