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
    std::string joints, body = "preset:male_average", sensors = "realworld", realism = "none", out, format = "csv";
    std::string activity = "synthetic";
    double fps = 20;            // HumanML3D's frame rate
    VirtualImuOptions options;  // rate and seed (their defaults); the realism model is set by the plan
};

std::string without_side(const std::string& position) {
    for (const char* prefix : {"left_", "right_"})
        if (position.rfind(prefix, 0) == 0) return position.substr(std::string(prefix).size());
    return position;
}

// What `imu synth` does, every spelling parsed and checked at the door.
struct ImuSynthPlan {
    std::string joints, out, format, activity;
    double fps = 20;
    std::vector<BodySpec> bodies;
    std::vector<SensorPlacement> sensors;
    VirtualImuOptions options;  // rate, seed and the parsed realism model
};

ImuSynthPlan plan_imu_synth(const SynthArgs& a) {
    ImuSynthPlan p{a.joints, a.out, a.format, a.activity, a.fps, {}, {}, a.options};
    check_usage([&] {
        p.bodies = parse_body_specs(a.body);
        p.sensors = parse_sensor_sets(a.sensors);
        check_motion_fps(a.fps, "--fps");
        p.options.set_realism(parse_realism(a.realism));
        p.options.validate();
        check_output(a.out, "--out", OutputKind::folder, {a.joints});
    });
    return p;
}

// Everything is computed before anything is written, and the folder appears complete or not at all.
void write_outputs(const ImuSynthPlan& p, const std::vector<BodyImu>& bodies, const nlohmann::json& meta) {
    remove_stale_partials(p.out);
    const fs::path tmp = partial_path_for(p.out);
    fs::remove_all(tmp);
    for (const BodyImu& b : bodies) {
        write_body_imu(tmp.string(), b);
        if (p.format != "realworld") continue;
        for (size_t i = 0; i < b.mounts.size(); ++i)
            write_realworld_csv((tmp / b.body.name).string(), p.activity, without_side(b.mounts[i].placement.position),
                                b.signals[i]);
    }
    write_file_atomic((tmp / "meta.json").string(), meta.dump(2) + "\n");
    publish_partial(tmp.string(), p.out);
}

void run(const ImuSynthPlan& p) {
    const JointSequence motion = joint_sequence_from_array(read_npy(p.joints), p.joints, 22, 4, p.fps);
    check_motion_for_imu(motion, p.joints);
    std::vector<BodyImu> results;
    for (const BodySpec& b : p.bodies) results.push_back(synthesize_body_imu(motion, b, p.sensors, p.options));
    write_outputs(p, results, virtual_imu_meta(results, motion, p.options, p.joints));
    std::printf("%s: %zu bodies x %zu sensors, %zu samples at %g Hz\n", p.out.c_str(), results.size(), p.sensors.size(),
                results[0].signals.empty() ? size_t{0} : results[0].signals[0].t.size(), p.options.rate_hz);
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
    cmd->add_option("--realism", a.realism, realism_help());
    cmd->add_option("--seed", a.options.seed, "seed of mounting errors, realism draws and noise");
    cmd->add_option("--format", a.format, "csv, or realworld to add RealWorld's release files")
        ->check(CLI::IsMember({"csv", "realworld"}));
    cmd->add_option("--activity", a.activity, "activity name in RealWorld file names");
    cmd->add_option("--out", a.out, "output folder")->required();
    cmd->callback([&a] { run(plan_imu_synth(a)); });
});

}  // namespace t2imu::cli
