#include "app/bench/bench_report.hpp"

#include "app/bench/charts.hpp"

#include <sstream>

namespace ecoview {
namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : c == '"' ? "&quot;" : std::string(1, c);
  return out;
}

}  // namespace

std::string pareto_summary_html(const nlohmann::json& fronts) {
  std::ostringstream html;
  html << "<h2>Summary: the best at each cost</h2>\n<p>Per scene, the methods on the Pareto front of frame time against "
          "err: those no other run beats in both, fastest first.</p>\n"
          "<table><tr><th>scene</th><th>method</th><th>map size</th><th>frame_ms</th><th>err (%)</th></tr>\n";
  for (const auto& [scene, front] : fronts.items()) {
    bool first = true;
    for (const nlohmann::json& point : front) {
      html << "<tr>";
      if (first) html << "<th rowspan=\"" << front.size() << "\">" << escaped(scene) << "</th>";
      first = false;
      const int size = point["shadow_size"].get<int>();
      html << "<td>" << escaped(point["method"].get<std::string>()) << "</td><td>" << (size > 0 ? std::to_string(size) + "²" : "—")
           << "</td><td>" << report_cell(point["frame_ms"]) << "</td><td>" << report_cell(nlohmann::json(100.0 * point["err"].get<double>()))
           << "</td></tr>\n";
    }
  }
  return html.str() + "</table>\n";
}

}  // namespace ecoview
