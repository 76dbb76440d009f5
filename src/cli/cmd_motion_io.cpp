// t2imu motion import | export: motion capture <-> SMPL-22 joints (.npy).
#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/npy.hpp"
#include "core/output_path.hpp"
#include "motion/bvh_export.hpp"
#include "motion/mocap_import.hpp"

namespace t2imu::cli {

static void add_import_command(CLI::App& motion) {
    auto* cmd =
        motion.add_subcommand("import", "BVH or ASF/AMC motion capture -> SMPL-22 joints [F,22,3] (metres, Y up)");
    auto& in = option_values<std::string>();
    auto& out = option_values<std::string>();
    auto& options = option_values<ImportOptions>();
    cmd->add_option("input", in, "motion file (.bvh, .amc, .npy)")->required()->check(CLI::ExistingFile);
    cmd->add_option("--out", out, "output joints .npy (float32)")->required();
    cmd->add_option("--fps", options.fps,
                    "output frame rate (0: the capture rate, decimated by a whole number to at most 60)")
        ->capture_default_str();
    cmd->add_option("--format", options.format, "bvh, amc or npy (default: by extension)");
    cmd->add_option("--asf", options.asf,
                    "ASF skeleton of an AMC clip (default: the .asf beside it named as its prefix)");
    cmd->add_option("--up", options.up, "the source's up axis: y or z (Z-up captures are turned to Y up)")
        ->capture_default_str()
        ->check(CLI::IsMember({'y', 'z'}));
    cmd->add_option("--source-fps", options.source_fps, "frame rate of an AMC clip (AMC does not record it)")
        ->capture_default_str();
    cmd->callback([&in, &options, &out] {
        check_usage([&in, &options, &out] {
            if (!(options.fps >= 0 && options.fps <= 1000))
                throw Error("--fps", "rate", "0 (the capture rate) to 1000 fps", std::to_string(options.fps));
            if (!(options.source_fps > 0 && options.source_fps <= 1000))
                throw Error("--source-fps", "rate", "above 0 and at most 1000 fps", std::to_string(options.source_fps));
            check_output(out, "--out", OutputKind::file, {in});
        });
        write_npy(out, joint_sequence_to_array(import_motion(in, options)));
    });
}

static void add_export_command(CLI::App& motion) {
    auto* cmd = motion.add_subcommand("export", "SMPL-22 joints [F,22,3] -> BVH (centimetres, Y up; opens in Blender)");
    auto& in = option_values<std::string>();
    auto& out = option_values<std::string>();
    auto& fps = option_values<double>(20.0);
    cmd->add_option("input", in, "joints .npy [F,22,3]")->required()->check(CLI::ExistingFile);
    cmd->add_option("--out", out, "output .bvh")->required();
    cmd->add_option("--fps", fps, "frame rate of the joints")->capture_default_str();
    cmd->callback([&fps, &in, &out] {
        check_usage([&fps, &in, &out] {
            check_motion_fps(fps, "--fps");
            check_output(out, "--out", OutputKind::file, {in});
        });
        write_bvh(out, smpl22_to_bvh(joint_sequence_from_array(read_npy(in), in, 22, 1, fps)));
    });
}

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& motion = command_group(root, "motion", "motion files: import, export, HumanML3D features");
    add_import_command(motion);
    add_export_command(motion);
});

}  // namespace t2imu::cli
