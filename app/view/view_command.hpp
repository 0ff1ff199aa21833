#pragma once
#include "app/cli/options.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace ecoview {

struct ViewOptions {
  SceneOptions scene;
  RenderOptions render;
  int exit_after = 0;  // frames; 0 runs until the window is closed
  std::string play;                 // camera path to follow from t = 0
  std::string record = "path.json";  // where R writes the recorded path
  std::optional<double> fps;         // none: real time; otherwise frame i is at time i / fps, as in capture
  std::string screenshot;            // the window as shown in the last frame
  std::string out = ".";             // where P writes frames as capture does
  bool no_hud = false;
  bool full_hud = false;
  bool shadow_map_inset = false;
  bool aliasing_overlay = false;
};

// Registers `ecoview view` on `app`.
CLI::App* add_view_command(CLI::App& app, ViewOptions& options);
// Shows the scene in a window until it is closed (or --exit-after); returns the exit code.
int run_view(const ViewOptions& options);

}  // namespace ecoview
