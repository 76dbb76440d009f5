// t2imu motion quality: plausibility scores of joint motions (motion_quality.hpp) as CSV, with the
// percentiles over all inputs; how the filter's default thresholds were measured on captured motion.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/atomic_file.hpp"
#include "core/npy.hpp"
#include "core/number_text.hpp"
#include "core/output_path.hpp"
#include "core/parse.hpp"
#include "motion/motion_quality.hpp"

namespace t2imu::cli {

namespace {

// A folder gives its *_joints.npy files (`t2imu sample` output, beside *_features.npy) or, with none, all of
// its .npy files (a dataset's new_joints/).
std::vector<std::string> joint_files(const std::vector<std::string>& inputs) {
    std::vector<std::string> out;
    for (const std::string& in : inputs) {
        if (!std::filesystem::is_directory(in)) {
            out.push_back(in);
            continue;
        }
        std::vector<std::string> npy, joints;
        for (const auto& e : std::filesystem::directory_iterator(in)) {
            const std::string path = e.path().string();
            if (ends_with(path, ".npy")) npy.push_back(path);
            if (ends_with(path, "_joints.npy")) joints.push_back(path);
        }
        out.insert(out.end(), joints.empty() ? npy.begin() : joints.begin(), joints.empty() ? npy.end() : joints.end());
    }
    std::sort(out.begin(), out.end());
    return out;
}

double percentile(std::vector<double> v, double p) {
    std::sort(v.begin(), v.end());
    return v[static_cast<size_t>(
        std::min<double>(static_cast<double>(v.size() - 1), p / 100.0 * static_cast<double>(v.size())))];
}

void run(const std::vector<std::string>& inputs, double fps, double p, const std::string& out) {
    std::string csv = "file";
    for (const char* name : kQualityScoreNames) csv += std::string(",") + name;
    csv += "\n";
    std::vector<std::vector<double>> columns(kNumQualityScores);
    for (const std::string& file : joint_files(inputs)) {
        const auto v = quality_scores(score_motion(joint_sequence_from_array(read_npy(file), file, 22, 3, fps)));
        csv += file;
        const int decimals[] = {4, 4, 4, 3, 2, 2};
        for (size_t i = 0; i < kNumQualityScores; ++i) csv += "," + fixed_text(v[i], decimals[i]);
        csv += "\n";
        for (size_t i = 0; i < kNumQualityScores; ++i) columns[i].push_back(v[i]);
    }
    if (columns[0].empty()) throw Error("motion quality", "inputs", "at least one joints .npy");
    if (!out.empty()) write_file_atomic(out, csv);
    const auto limit = quality_limits(default_quality_thresholds());
    std::printf("%zu motions: score, %g-th percentile, default threshold, share over it\n", columns[0].size(), p);
    for (size_t i = 0; i < kNumQualityScores; ++i) {
        const auto over = std::count_if(columns[i].begin(), columns[i].end(), [&](double v) { return v > limit[i]; });
        std::printf("  %-15s %10.4f %10.4f %7.2f %%\n", kQualityScoreNames[i], percentile(columns[i], p), limit[i],
                    100.0 * static_cast<double>(over) / static_cast<double>(columns[i].size()));
    }
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& motion = command_group(root, "motion", "motion files: import, export, HumanML3D features");
    auto* cmd = motion.add_subcommand(
        "quality", "plausibility scores (foot skating, floor, speed, acceleration) of joints .npy files");
    auto& inputs = option_values<std::vector<std::string>>();
    auto& fps = option_values<double>(20);
    auto& p = option_values<double>(99.5);
    auto& out = option_values<std::string>();
    cmd->add_option("inputs", inputs, "joints .npy [F,22,3] files, or folders of them (*_joints.npy where present)")
        ->required();
    cmd->add_option("--fps", fps, "frame rate of the joints")->capture_default_str();
    cmd->add_option("--percentile", p, "percentile to print over the inputs")->capture_default_str();
    cmd->add_option("--out", out, "per-file scores CSV");
    cmd->callback([&fps, &inputs, &out, &p] {
        check_usage([&fps, &inputs, &out, &p] {
            check_motion_fps(fps, "--fps");
            if (!(p >= 0 && p <= 100)) throw Error("--percentile", "percentile", "0 to 100", std::to_string(p));
            if (!out.empty()) check_output(out, "--out", OutputKind::file, inputs);
        });
        run(inputs, fps, p, out);
    });
});

}  // namespace t2imu::cli
