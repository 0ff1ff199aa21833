#pragma once
#include "app/cli/options.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace ecoview {

struct DensityOptions {
  std::string scene;
  BenchmarkOptions run{"960x540"};
};

// Registers `ecoview density`: the point-density benchmark (sweeps of k, splat size and instance
// count; results.json, results.csv, charts, report.html).
CLI::App* add_density_command(CLI::App& app, DensityOptions& options);
int run_density(const DensityOptions& options);

}  // namespace ecoview
