#include "app/bench/charts.hpp"

#include "app/errors.hpp"
#include "app/file_io.hpp"
#include "app/resources.hpp"

#include <cstdlib>
#include <sstream>

namespace ecoview {
namespace {

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string run_table(const BenchResults& results) {
  std::ostringstream html;
  html << "<table><tr><th>params</th><th>figures</th></tr>\n";
  for (const BenchRun& run : results.runs) {
    html << "<tr><td>";
    for (const auto& p : run.params.items()) html << p.key() << "=" << report_cell(p.value()) << " ";
    html << "</td><td>";
    for (const auto& f : run.figures.items()) html << f.key() << "=" << report_cell(f.value()) << " ";
    html << "</td></tr>\n";
  }
  return html.str() + "</table>\n";
}

std::string machine_table(const nlohmann::json& machine) {
  std::ostringstream html;
  html << "<table>\n";
  for (const auto& item : machine.items()) html << "<tr><th>" << item.key() << "</th><td>" << report_cell(item.value()) << "</td></tr>\n";
  return html.str() + "</table>\n";
}

}  // namespace

std::string report_cell(const nlohmann::json& v) {
  if (v.is_number_float()) {
    std::ostringstream s;
    s.precision(4);
    s << v.get<double>();
    return s.str();
  }
  return v.is_string() ? v.get<std::string>() : v.dump();
}

void draw_charts(const std::filesystem::path& folder, const std::string& script) {
  const auto text = resources::find("scripts/plots/" + script);
  const std::filesystem::path script_file = folder / script;
  write_file_atomically(script_file, *text);
  const std::string command = "/usr/bin/python3 " + shell_quote(script_file.string()) + " " +
                              shell_quote((folder / "results.json").string()) + " " + shell_quote(folder.string());
  const int status = std::system(command.c_str());
  std::filesystem::remove(script_file);
  if (status != 0) {
    throw RuntimeFailure("charts: /usr/bin/python3 with matplotlib failed (install python3-matplotlib); results.json "
                         "and results.csv are written in " + folder.string());
  }
}

void write_report(const std::filesystem::path& folder, const std::string& title, const std::string& summary,
                  const std::string& body, const BenchResults& results) {
  const bool quick = results.quick;
  std::ostringstream html;
  html << "<!doctype html><html><head><meta charset=\"utf-8\"><title>" << title << "</title><style>"
          "body{font-family:sans-serif;margin:2em}td,th{border:1px solid #ccc;padding:3px;font-size:12px}"
          "table{border-collapse:collapse}img{max-width:100%}.quick{background:#fe9;padding:0.5em}</style></head><body>\n"
       << "<h1>" << title << (quick ? " (quick run)" : "") << "</h1>\n";
  if (quick) html << "<p class=\"quick\">A quick run (--quick): small scenes and few frames, to check that everything works. Its numbers are not for comparison.</p>\n";
  html << summary << "<h2>Machine</h2>\n" << machine_table(results.machine) << body << "<h2>Runs</h2>\n" << run_table(results) << "</body></html>\n";
  write_file_atomically(folder / "report.html", html.str());
}

}  // namespace ecoview
