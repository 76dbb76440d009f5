// --sampler for the commands that sample a diffusion model: the names of diffusion/samplers.hpp's table, refused
// by CLI11 otherwise (exit 2, like any flag value it refuses).
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "diffusion/sample_options.hpp"

namespace t2imu::cli {

inline CLI::Option* add_sampler_option(CLI::App& cmd, Sampler& sampler, const std::string& help) {
    return cmd
        .add_option_function<std::string>(
            "--sampler", [&sampler](const std::string& name) { sampler = parse_sampler(name); }, help)
        ->check(CLI::IsMember(sampler_names()));
}

}  // namespace t2imu::cli
