#pragma once
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace ecoview {

// One measured configuration: its parameters and figures, named as in DESIGN.md.
struct BenchRun {
  nlohmann::json params = nlohmann::json::object();
  nlohmann::json figures = nlohmann::json::object();
};

// What `bench` and `density` write: results.json {"machine", "runs"} and results.csv (one row a
// run, a column for every parameter and figure that any run has).
struct BenchResults {
  nlohmann::json machine = nlohmann::json::object();
  std::vector<BenchRun> runs;
};

void write_results(const std::filesystem::path& folder, const BenchResults& results);

// The machine block: GL renderer, cores, backend, the git commit the binary was built from.
nlohmann::json machine_info(const std::string& renderer, const std::string& backend);

}  // namespace ecoview
