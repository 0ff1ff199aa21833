#pragma once
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ecoview {

// One measured configuration: its parameters and figures, named as docs/figures.md names them. A figure
// measured by repeats (a time: the median of several frames) has its spread beside it, named
// with spread_suffix ("frame_ms_spread"); any other figure is deterministic, its spread 0.
struct BenchRun {
  nlohmann::json params = nlohmann::json::object();
  nlohmann::json figures = nlohmann::json::object();
};
constexpr std::string_view spread_suffix = "_spread";

// What `bench` and `density` write: results.json {"machine", "quick", "runs", then `sections`}
// and results.csv (one row a run, a column for every parameter and figure that any run has).
struct BenchResults {
  nlohmann::json machine = nlohmann::json::object();
  bool quick = false;  // --quick: a check that everything works, its numbers not for comparison
  std::vector<BenchRun> runs;
  nlohmann::json sections = nlohmann::json::object();  // what a command adds: bench's pareto_front, baseline
};

void write_results(const std::filesystem::path& folder, const BenchResults& results);

// A results.json as write_results writes it: machine, quick (false where absent: files from
// before it), runs with params and figures, every figure a finite number. Throws InputError
// naming the file and the field otherwise.
BenchResults read_results(const std::filesystem::path& file);

// The machine block: CPU model, cores, GL renderer and version, backend, compiler, and the git
// commit the binary was built from. Reads the current GL context's version.
nlohmann::json machine_info(const std::string& renderer, const std::string& backend);

// The CPU's model as /proc/cpuinfo's text names it (its first "model name", else "Hardware" or
// "Processor", which ARM kernels give), or "unknown".
std::string cpu_model(const std::string& cpuinfo);

}  // namespace ecoview
