// t2imu data import-imu: a real IMU dataset in its release format -> the common IMU layout.
#include <cstdio>

#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "har/datasets/importers.hpp"
#include "imu/dataset_profile.hpp"
#include "imu/imu_dataset.hpp"

namespace t2imu::cli {

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& data = command_group(root, "data", "training and IMU datasets");
    auto* cmd =
        data.add_subcommand("import-imu", "real IMU dataset (release format) -> manifest.csv + one CSV per recording");
    auto& format = option_values<std::string>();
    auto& in = option_values<std::string>();
    auto& out = option_values<std::string>();
    cmd->add_option("--format", format, "release format: " + dataset_profile_names())->required();
    cmd->add_option("input", in, "folder of the release files")->required()->check(CLI::ExistingDirectory);
    cmd->add_option("--out", out, "output dataset folder")->required();
    cmd->callback([&in, &out, &format] {
        const DatasetProfile* profile = nullptr;
        check_usage([&] {
            profile = find_dataset_profile(format);
            if (!profile) throw Error("--format", "format", dataset_profile_names(), format);
            check_output(out, "--out", OutputKind::folder, {in});
        });
        std::vector<std::string> skipped;
        const std::vector<ImuRecording> recordings = import_imu_dataset(*profile, in, &skipped);
        remove_stale_partials(out);
        const std::string partial = partial_path_for(out);
        write_imu_dataset(partial, recordings);
        publish_partial(partial, out);  // the folder appears whole or not at all
        std::printf("%s: %zu recordings, %zu files skipped\n", out.c_str(), recordings.size(), skipped.size());
        for (const std::string& s : skipped) std::printf("skipped: %s\n", s.c_str());
    });
});

}  // namespace t2imu::cli
