#pragma once
#include "app/cli/options.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace ecoview {

struct ViewOptions {
  std::string scene;
  RenderOptions render;
  int light = 0;
  int exit_after = 0;  // frames; 0 runs until the window is closed
  double memory_budget_gib = 4.0;
};

// Registers `ecoview view` on `app`.
CLI::App* add_view_command(CLI::App& app, ViewOptions& options);
// Shows the scene in a window until it is closed; returns the exit code.
int run_view(const ViewOptions& options);

}  // namespace ecoview
