#pragma once
#include "app/cli/options.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace ecoview {

struct DensityOptions {
  std::string scene;
  std::string size = "960x540";
  std::string backend = "egl";
  bool quick = false;  // a few short runs, to check the pipeline (tests)
  double memory_budget_gib = 4.0;
  std::string out;
};

// Registers `ecoview density`: the point-density benchmark (sweeps of k, splat size and instance
// count; results.json, results.csv, charts, report.html).
CLI::App* add_density_command(CLI::App& app, DensityOptions& options);
int run_density(const DensityOptions& options);

}  // namespace ecoview
