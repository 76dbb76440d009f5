// t2imu imu synth: joints [F,22,3] -> bodies -> virtual accelerometers and gyroscopes.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "core/output_path.hpp"
#include "imu/dataset_profile.hpp"
#include "imu/imu_dataset.hpp"
#include "imu/realism.hpp"
#include "imu/realworld_export.hpp"
#include "imu/virtual_imu.hpp"

namespace t2imu::cli {

namespace fs = std::filesystem;

namespace {

struct SynthArgs {
    std::string joints, body = "preset:male_average", sensors = "realworld", noise = "none", realism = "none", out,
                        format = "csv";
    std::string activity = "synthetic";
    double fps = 20;            // HumanML3D's frame rate
    VirtualImuOptions options;  // rate and seed (their defaults); the realism model is set once parsed
};

std::string without_side(const std::string& position) {
    for (const char* prefix : {"left_", "right_"})
        if (position.rfind(prefix, 0) == 0) return position.substr(std::string(prefix).size());
    return position;
}

// Everything is computed before anything is written, and the folder appears complete or not at all.
void write_outputs(const SynthArgs& a, const std::vector<BodyImu>& bodies, const nlohmann::json& meta) {
    remove_stale_partials(a.out);
    const fs::path tmp = partial_path_for(a.out);
    fs::remove_all(tmp);
    for (const BodyImu& b : bodies) {
        write_body_imu(tmp.string(), b);
        if (a.format != "realworld") continue;
        for (size_t i = 0; i < b.mounts.size(); ++i)
            write_realworld_csv((tmp / b.body.name).string(), a.activity, without_side(b.mounts[i].placement.position),
                                b.signals[i]);
    }
    write_file_atomic((tmp / "meta.json").string(), meta.dump(2) + "\n");
    publish_partial(tmp.string(), a.out);
}

void run(const SynthArgs& a) {
    VirtualImuOptions options = a.options;
    std::vector<BodySpec> bodies;
    std::vector<SensorPlacement> sensors;
    check_usage([&] {  // every spelling parsed here, once, before any work
        bodies = parse_body_specs(a.body);
        sensors = parse_sensor_sets(a.sensors);
        check_motion_fps(a.fps, "--fps");
        RealismModel realism = parse_realism(a.realism);
        fold_noise_option(a.noise, &realism);
        options.set_realism(realism);
        options.validate();
        check_output(a.out, "--out", OutputKind::folder, {a.joints});
    });
    const JointSequence motion = joint_sequence_from_array(read_npy(a.joints), a.joints, 22, 4, a.fps);
    check_motion_for_imu(motion, a.joints);
    std::vector<BodyImu> results;
    for (const BodySpec& b : bodies) results.push_back(synthesize_body_imu(motion, b, sensors, options));
    write_outputs(a, results, virtual_imu_meta(results, motion, options, a.joints));
    std::printf("%s: %zu bodies x %zu sensors, %zu samples at %g Hz\n", a.out.c_str(), results.size(), sensors.size(),
                results[0].signals.empty() ? size_t{0} : results[0].signals[0].t.size(), options.rate_hz);
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& imu = command_group(root, "imu", "virtual IMUs on bodies");
    auto* cmd =
        imu.add_subcommand("synth", "joints [F,22,3] -> accelerometer + gyroscope CSVs per body and sensor position");
    auto& a = option_values<SynthArgs>();
    cmd->add_option("--joints", a.joints, "joints .npy [F,22,3], metres, Y up")->required()->check(CLI::ExistingFile);
    cmd->add_option("--fps", a.fps, "frame rate of the joints (HumanML3D: 20)");
    cmd->add_option("--body", a.body,
                    "preset:NAME | paper8 | population:N[,seed=S,female=F,height_m|height_f=CM:SD,bmi_m|bmi_f=MEAN:SD] "
                    "| height=CM,mass=KG,sex=m|f | smpl:FILE.npz[,betas=..] | none; join with +");
    cmd->add_option("--sensors", a.sensors,
                    "placement sets: " + dataset_profile_names() + ", FILE.toml (comma-separated)");
    cmd->add_option("--rate", a.options.rate_hz, "output sample rate, Hz");
    cmd->add_option("--noise", a.noise,
                    "the sensor's errors alone (the realism model's sensor key): none | smartphone | hugadb | sisfall "
                    "| umafall [,key=value...]");
    cmd->add_option("--realism", a.realism, realism_help());
    cmd->add_option("--seed", a.options.seed, "seed of mounting errors, realism draws and noise");
    cmd->add_option("--format", a.format, "csv, or realworld to add RealWorld's release files")
        ->check(CLI::IsMember({"csv", "realworld"}));
    cmd->add_option("--activity", a.activity, "activity name in RealWorld file names");
    cmd->add_option("--out", a.out, "output folder")->required();
    cmd->callback([&a] { run(a); });
});

}  // namespace t2imu::cli
