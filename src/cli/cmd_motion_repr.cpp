// t2imu motion features | joints: HumanML3D's process_file and recover_from_ric on .npy files.
#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/npy.hpp"
#include "core/output_path.hpp"
#include "motion/humanml3d.hpp"

namespace t2imu::cli {

static void add_features_command(CLI::App& motion) {
    auto* cmd =
        motion.add_subcommand("features", "joints [F,22,3] (metres, Y up, 20 fps) -> HumanML3D features [F-1,263]");
    auto& in = option_values<std::string>();
    auto& out = option_values<std::string>();
    cmd->add_option("--joints", in, "input joints .npy")->required()->check(CLI::ExistingFile);
    cmd->add_option("--out", out, "output features .npy (float32)")->required();
    cmd->callback([&in, &out] {
        check_usage([&in, &out] { check_output(out, "--out", OutputKind::file, {in}); });
        const JointSequence joints = joint_sequence_from_array(read_npy(in), in, 22, 2);
        write_npy(out, feature_matrix_to_array(joints_to_features(joints)));
    });
}

static void add_joints_command(CLI::App& motion) {
    auto* cmd = motion.add_subcommand("joints", "HumanML3D features [F,263] -> joints [F,22,3] (recover_from_ric)");
    auto& in = option_values<std::string>();
    auto& out = option_values<std::string>();
    cmd->add_option("--features", in, "input features .npy (not normalised)")->required()->check(CLI::ExistingFile);
    cmd->add_option("--out", out, "output joints .npy (float32)")->required();
    cmd->callback([&in, &out] {
        check_usage([&in, &out] { check_output(out, "--out", OutputKind::file, {in}); });
        const FeatureMatrix features = feature_matrix_from_array(read_npy(in), in, kFeatureDim);
        if (features.rows() < 1) throw Error(in, "shape", "at least one frame", "0");
        write_npy(out, joint_sequence_to_array(recover_from_ric(features)));
    });
}

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& motion = command_group(root, "motion", "motion files: import, export, HumanML3D features");
    add_features_command(motion);
    add_joints_command(motion);
});

}  // namespace t2imu::cli
