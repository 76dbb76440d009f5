// t2imu motion describe: what a caption could say of each motion, measured from its joints
// (motion/motion_attributes.hpp): speed, cadence, turns, steps, jumps, posture and transitions, as CSV.
#include <cstdio>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/output_path.hpp"
#include "motion/mocap_import.hpp"
#include "motion/motion_attributes.hpp"

namespace t2imu::cli {

namespace {

struct DescribeArgs {
    std::vector<std::string> inputs;
    double fps = 20.0;
    std::string out;
};

CsvTable describe(const DescribeArgs& a) {
    CsvTable t;
    t.header = {"file"};
    for (const auto& [name, value] : attribute_fields(MotionAttributes{})) t.header.push_back(name);
    for (const std::string& path : a.inputs) {
        ImportOptions o;
        o.fps = a.fps;
        std::vector<std::string> row = {path};
        for (const auto& [name, value] : attribute_fields(measure_attributes(import_motion(path, o), path)))
            row.push_back(value);
        t.rows.push_back(std::move(row));
    }
    return t;
}

}  // namespace

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& motion = command_group(root, "motion", "motion files: import, export, HumanML3D features");
    auto* cmd = motion.add_subcommand(
        "describe", "measure what a caption could say of motions (speed, turns, steps, jumps, posture) -> CSV");
    auto& a = option_values<DescribeArgs>();
    cmd->add_option("inputs", a.inputs, "motion files: SMPL-22 joints .npy [F,22,3] (metres, Y up), .bvh or .amc")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--fps", a.fps, "frame rate of .npy joints (BVH and AMC are resampled to it)")
        ->capture_default_str();
    cmd->add_option("--out", a.out, "write the CSV here (default: print it)");
    cmd->callback([&a] {
        check_usage([&a] {
            check_motion_fps(a.fps, "--fps");
            if (!a.out.empty()) check_output(a.out, "--out", OutputKind::file, a.inputs);
        });
        const std::string text = format_csv(describe(a));
        if (a.out.empty())
            std::fputs(text.c_str(), stdout);
        else
            write_file_atomic(a.out, text);
    });
});

}  // namespace t2imu::cli
