#pragma once
#include <CLI/CLI.hpp>

namespace ecoview {

// `ecoview scenes`: the scenes and camera paths compiled into the binary, a line each.
CLI::App* add_scenes_command(CLI::App& app);
int run_scenes();

}  // namespace ecoview
