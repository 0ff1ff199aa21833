#pragma once
#include "app/cli/options.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace ecoview {

struct CaptureOptions {
  SceneOptions scene;
  std::string path;
  RenderOptions render;
  std::string backend = "egl";
  std::string frames;
  double fps = 30.0;
  std::string aov = "color";
  std::string aov_format = "png";
  bool force = false;
  std::string stats;  // per-frame figures as JSON, when not empty
  std::string out;
  std::string video;  // an MP4 of the color frames, when not empty
};

// Registers `ecoview capture` and its options on `app`.
CLI::App* add_capture_command(CLI::App& app, CaptureOptions& options);
// Renders the frames; returns the exit code. Throws InputError / RuntimeFailure.
int run_capture(const CaptureOptions& options);

}  // namespace ecoview
