#include "app/bench/bench_report.hpp"

#include "app/bench/charts.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ecoview {
namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : c == '"' ? "&quot;" : std::string(1, c);
  return out;
}

std::string params_text(const nlohmann::json& params) {
  std::string text;
  for (const auto& p : params.items()) text += (text.empty() ? "" : " ") + p.key() + "=" + report_cell(p.value());
  return escaped(text);
}

double relative_change(const nlohmann::json& change) {
  const double old_value = change["old"].get<double>(), new_value = change["new"].get<double>();
  return old_value == 0.0 ? (new_value == 0.0 ? 0.0 : INFINITY) : (new_value - old_value) / std::abs(old_value);
}

std::string change_table(std::vector<nlohmann::json> changes) {
  std::stable_sort(changes.begin(), changes.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
    return std::abs(relative_change(a)) > std::abs(relative_change(b));
  });
  std::ostringstream html;
  html << "<table><tr><th>configuration</th><th>figure</th><th>old ± spread</th><th>new ± spread</th><th>change</th></tr>\n";
  for (const nlohmann::json& c : changes) {
    std::ostringstream percent;
    percent.precision(3);
    percent << std::showpos << 100.0 * relative_change(c) << " %";
    html << "<tr><td>" << params_text(c["params"]) << "</td><td>" << escaped(c["figure"].get<std::string>()) << "</td><td>"
         << report_cell(c["old"]) << " ± " << report_cell(c["old_spread"]) << "</td><td>" << report_cell(c["new"]) << " ± "
         << report_cell(c["new_spread"]) << "</td><td>" << percent.str() << "</td></tr>\n";
  }
  return html.str() + "</table>\n";
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

std::string baseline_html(const nlohmann::json& section) {
  std::vector<nlohmann::json> flagged, within;
  for (const nlohmann::json& c : section["changes"]) {
    if (c["flagged"].get<bool>()) flagged.push_back(c);
    else if (c["new"] != c["old"]) within.push_back(c);
  }
  std::ostringstream html;
  html << "<h2>Against the baseline</h2>\n<p>Baseline " << escaped(section["file"].get<std::string>()) << " (git "
       << escaped(section["git"].get<std::string>()) << (section["quick"].get<bool>() ? ", a quick run" : "") << "): "
       << section["changes"].size() << " figures compared, <b>" << flagged.size() << " flagged</b> (" << section["rule"].get<std::string>()
       << "; a time's spread is the interquartile range of its frames, any other figure's is 0), " << within.size()
       << " changed within the spread. Configurations only in this run: " << section["runs_only_here"]
       << "; only in the baseline: " << section["runs_only_in_baseline"] << ".</p>\n"
       << change_table(flagged) << "<details><summary>Changes within the spread (" << within.size() << ")</summary>\n"
       << change_table(within) << "</details>\n";
  return html.str();
}

std::string crops_html(const std::map<std::string, std::vector<std::string>>& methods_by_scene, int map_size) {
  std::ostringstream html;
  html << "<h2>Crops (" << map_size << "² maps, where the first method's shadows have the most edges; pixels magnified)</h2>\n";
  for (const auto& [scene, methods] : methods_by_scene) {
    html << "<h3>" << escaped(scene) << "</h3><table><tr><th>method</th><th>its crop</th><th>the reference's</th></tr>\n";
    for (const std::string& m : methods) {
      if (m == "reference") continue;
      html << "<tr><th>" << escaped(m) << "</th><td><img src=\"images/crop_" << scene << "_" << m
           << ".png\"></td><td><img src=\"images/crop_" << scene << "_reference.png\"></td></tr>\n";
    }
    html << "</table>\n";
  }
  return html.str();
}

}  // namespace ecoview
