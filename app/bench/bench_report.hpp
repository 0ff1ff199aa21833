#pragma once
#include <nlohmann/json.hpp>

#include <map>
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

// Per scene, each method's crop beside the reference's (images/crop_<scene>_<method>.png).
std::string crops_html(const std::map<std::string, std::vector<std::string>>& methods_by_scene, int map_size);

}  // namespace ecoview
