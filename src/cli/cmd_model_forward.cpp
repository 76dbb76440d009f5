// t2imu model forward: one denoiser pass on arrays in the official layouts (for checks against PyTorch).
#include "cli/command.hpp"
#include "cli/usage.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "core/output_path.hpp"
#include "diffusion/mdm_io.hpp"
#include "diffusion/sample_options.hpp"

namespace t2imu::cli {

static CommandRegistrar registrar([](CLI::App& root) {
    CLI::App& model = command_group(root, "model", "denoiser checks");
    auto* cmd = model.add_subcommand(
        "forward", "MDM forward pass: x [B,263,1,F], timesteps [B], text embeddings [B,D] -> [B,263,1,F]");
    auto& f = option_values<MdmForwardFiles>();
    cmd->add_option("--weights", f.weights, "safetensors with the official state-dict names")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--config", f.config, "args.json-like configuration")->required()->check(CLI::ExistingFile);
    cmd->add_option("--x", f.x, "noised motions .npy [B,263,1,F]")->required()->check(CLI::ExistingFile);
    cmd->add_option("--timesteps", f.timesteps, "diffusion steps .npy [B] (integers)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--text-embed", f.text, "text embeddings .npy [B,D]")->required()->check(CLI::ExistingFile);
    cmd->add_option("--lengths", f.lengths, "valid frames .npy [B] (used when the config sets mask_frames)")
        ->check(CLI::ExistingFile);
    auto* uncond = cmd->add_flag("--uncond", f.uncond, "the unconditional pass (text zeroed)");
    cmd->add_option("--guidance", f.guidance, "classifier-free guidance scale (uncond + s (cond - uncond))")
        ->excludes(uncond);
    cmd->add_option("--out", f.out, "output .npy [B,263,1,F] float32")->required();
    cmd->callback([&f] {
        check_usage([&f] {
            check_guidance_scale(f.guidance, "--guidance");
            check_output(f.out, "--out", OutputKind::file, {f.weights, f.config, f.x, f.timesteps, f.text, f.lengths});
        });
        run_mdm_forward(f);
    });
});

}  // namespace t2imu::cli
