#pragma once
#include "app/bench/results.hpp"

#include <filesystem>
#include <string>

namespace ecoview {

// Runs the embedded chart script scripts/plots/<script> on folder/results.json with the
// system's python3 and matplotlib; it writes its PNG charts into the folder. Throws
// RuntimeFailure when python3-matplotlib is missing.
void draw_charts(const std::filesystem::path& folder, const std::string& script);

// folder/report.html: the title (marked when the run was `quick`: its numbers are not for
// comparison), `summary` (HTML: what a reader takes away, first), the machine as a table, `body`
// (HTML: charts, images) and every run's parameters and figures.
void write_report(const std::filesystem::path& folder, const std::string& title, const std::string& summary,
                  const std::string& body, const BenchResults& results);

// A value as the report's tables show it: numbers to 4 significant digits, strings as they are.
std::string report_cell(const nlohmann::json& value);

}  // namespace ecoview
