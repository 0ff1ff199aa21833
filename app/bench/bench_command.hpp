#pragma once
#include "app/cli/options.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace ecoview {

struct BenchOptions {
  BenchmarkOptions run{"640x360"};  // --quick: small scenes and a few configurations
  std::string suite = "methods";    // or "paper" (app/bench/paper_suite.hpp)
  std::string baseline;             // an earlier run's results.json to compare with (app/bench/baseline.hpp)
};

// Registers `ecoview bench`: shadow methods, speed against accuracy against the exact reference
// (sweeps of map size, light direction, a point light crossing the camera plane, a flythrough);
// results.json, results.csv, charts, image crops and report.html.
CLI::App* add_bench_command(CLI::App& app, BenchOptions& options);
int run_bench(const BenchOptions& options);

}  // namespace ecoview
