#pragma once
#include <nlohmann/json.hpp>

#include <string>

namespace ecoview {

// The parts of bench's report.html that bench alone has, as HTML.

// The summary it opens with: per scene, the runs on the Pareto front (pareto_fronts' JSON), as
// one table, fastest first.
std::string pareto_summary_html(const nlohmann::json& fronts);

}  // namespace ecoview
