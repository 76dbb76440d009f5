// t2imu data build: motion capture + captions -> a training set in the HumanML3D layout.
#include <cstdio>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/output_path.hpp"
#include "core/parse.hpp"
#include "data/dataset_builder.hpp"

namespace t2imu::cli {

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& data = command_group(root, "data", "training and IMU datasets");
    auto* cmd = data.add_subcommand(
        "build", "motion capture + captions -> HumanML3D layout (new_joint_vecs, texts, Mean/Std, splits)");
    auto& o = option_values<BuildOptions>();
    auto& licences = option_values<std::string>();
    cmd->add_option("--mocap", o.mocap_dir, "folder of motion files (the paths in the captions CSV are relative to it)")
        ->required()
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--captions", o.captions_csv,
                    "captions CSV: file,start_frame,end_frame,caption[,tokens,licence,subject,source] (default: "
                    "MOCAP/captions.csv)");
    cmd->add_option("--out", o.out_dir, "output dataset folder (replaced when complete)")->required();
    cmd->add_flag("--mirror", o.mirror,
                  "add left-right mirrored copies (ids prefixed M, captions with left/right swapped)");
    cmd->add_option("--licences", licences,
                    "keep only these, comma-separated: CMU, HDM05, BandaiNamco, KIT-ML (default: all)");
    cmd->add_option("--max-seconds", o.max_seconds, "cut longer clips into equal chunks no longer than this")
        ->capture_default_str();
    cmd->add_option("--max-seconds-per-file", o.max_seconds_per_file,
                    "keep at most this much of one recording, as chunks spread over it (0 = all)")
        ->capture_default_str();
    cmd->add_flag("--no-derived{false}", o.derive,
                  "leave out the clips derived from captured ones (stairs, sitting; see data/derived_clips.hpp)");
    cmd->add_flag("--lying-turns", o.derived_kinds.lying_turns,
                  "add lying clips turning onto the side and back (off by default; docs/realism.md on lying turns)");
    cmd->add_flag("--lie-down-rests", o.derived_kinds.lie_down_rests,
                  "add lying clips of the captured lie-down followed by rest (off by default; data/derived_clips.hpp)");
    cmd->add_flag("--stairs-round-trips", o.derived_kinds.stairs_round_trips,
                  "add stairs clips going up a flight and down the next (off by default; docs/data.md)");
    cmd->add_flag("--no-capture-rate{false}", o.capture_rate,
                  "do not keep captured clips at their capture rate (capture_joints/, what retrieval gives the "
                  "sensors), and derive clips at 20 fps");
    cmd->add_flag("--turning-walks", o.derived_kinds.turning_walks,
                  "add walks turned onto a curve, left, right or around (off by default; docs/attributes.md)");
    cmd->add_option(
           "--measured-captions", o.measured_captions,
           "add up to N captions per clip written from its measured motion (speed, turns, steps; docs/attributes.md)")
        ->capture_default_str();
    cmd->add_flag("--strict", o.strict, "stop at the first clip that fails to import (default: skip and report it)");
    cmd->callback([&licences, &o] {
        for (const std::string& item : split_list(licences)) o.licences.insert(item);
        check_usage([&o] {
            o.validate();
            check_output(o.out_dir, "--out", OutputKind::folder, {o.mocap_dir, o.captions_csv});
        });
        const BuildSummary s = build_dataset(o);
        std::printf("%s: %d clips, %.1f minutes, %d captions, %d files skipped\n", o.out_dir.c_str(), s.clips,
                    s.minutes, s.captions, s.skipped_files);
        std::printf("summary: %s/summary.json\n%s\n", o.out_dir.c_str(), s.json.c_str());
    });
});

}  // namespace t2imu::cli
