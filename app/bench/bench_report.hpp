#pragma once
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ecoview {

// The parts of bench's report.html that bench alone has, as HTML.

// The summary it opens with: per scene, the runs on the Pareto front (pareto_fronts' JSON), as
// one table, fastest first.
std::string pareto_summary_html(const nlohmann::json& fronts);

// The changes against a baseline (baseline_section's JSON): the flagged ones in a table, largest
// relative change first; those within the spread folded away below it.
std::string baseline_html(const nlohmann::json& section);

}  // namespace ecoview
