#pragma once
#include "app/bench/results.hpp"

#include <filesystem>

namespace ecoview {

// The PNG charts (drawn by the embedded scripts/plots/density_charts.py with the system's
// python3 and matplotlib) and report.html, which gathers them with the run table and images.
// Throws RuntimeFailure when python3-matplotlib is missing.
void write_charts(const std::filesystem::path& folder, const BenchResults& results);

}  // namespace ecoview
