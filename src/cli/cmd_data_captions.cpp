// t2imu data captions: a training set's captions, each under its clip's activity, as a model folder's
// captions.tsv (the caption anchor's, text/training_captions.hpp). t2imu train writes it into the models it
// trains; this gives it to a model trained before the anchor existed.
#include <cstdio>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "data/hml3d_dataset.hpp"
#include "text/training_captions.hpp"

namespace t2imu::cli {

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& data = command_group(root, "data", "training and IMU datasets");
    auto* cmd = data.add_subcommand(
        "captions", "a training set's captions under their clips' activities (a model folder's captions.tsv)");
    auto& dataset = option_values<std::string>();
    auto& split = option_values<std::string>("train");
    auto& out = option_values<std::string>();
    cmd->add_option("--dataset", dataset,
                    "training set (HumanML3D layout; clips.csv, when present, gives the activities)")
        ->required()
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--split", split, "the split the model was trained on: train, val, test or all")
        ->capture_default_str();
    cmd->add_option("--out", out, "output file (activity<TAB>caption)")->required();
    cmd->callback([&dataset, &out, &split] {
        check_usage([&dataset, &out, &split] {
            if (split != "train" && split != "val" && split != "test" && split != "all")
                throw Error("--split", "split", "train, val, test or all", split);
            check_output(out, "--out", OutputKind::file, {dataset});
        });
        const Hml3dDataset data(dataset, split);
        const auto captions = training_captions(data, dataset);
        write_training_captions(out, captions);
        std::printf("%s: %zu captions of %zu clips\n", out.c_str(), captions.size(), data.clips().size());
    });
});

}  // namespace t2imu::cli
