#include "app/bench/results.hpp"

#include "app/file_io.hpp"
#include "git_commit.hpp"

#include <set>
#include <sstream>
#include <thread>

namespace ecoview {
namespace {

// A field as RFC 4180 writes it: quoted, with quotes doubled, when it holds a comma, a quote or a
// line break (setup descriptions have commas).
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csv_cell(const nlohmann::json& v) {
  if (v.is_null()) return "";
  return csv_field(v.is_string() ? v.get<std::string>() : v.dump());
}

}  // namespace

void write_results(const std::filesystem::path& folder, const BenchResults& results) {
  nlohmann::json runs = nlohmann::json::array();
  std::set<std::string> param_names, figure_names;
  for (const BenchRun& run : results.runs) {
    runs.push_back({{"params", run.params}, {"figures", run.figures}});
    for (const auto& item : run.params.items()) param_names.insert(item.key());
    for (const auto& item : run.figures.items()) figure_names.insert(item.key());
  }
  const nlohmann::json document = {{"machine", results.machine}, {"runs", runs}};
  write_file_atomically(folder / "results.json", document.dump(2) + "\n");

  // RFC 4180: a header, one record a run, CRLF after each.
  std::ostringstream csv;
  bool first = true;
  for (const std::string& name : param_names) csv << (first ? "" : ",") << csv_field(name), first = false;
  for (const std::string& name : figure_names) csv << (first ? "" : ",") << csv_field(name), first = false;
  csv << "\r\n";
  for (const BenchRun& run : results.runs) {
    first = true;
    for (const std::string& name : param_names) csv << (first ? "" : ",") << csv_cell(run.params.value(name, nlohmann::json())), first = false;
    for (const std::string& name : figure_names) csv << (first ? "" : ",") << csv_cell(run.figures.value(name, nlohmann::json())), first = false;
    csv << "\r\n";
  }
  write_file_atomically(folder / "results.csv", csv.str());
}

nlohmann::json machine_info(const std::string& renderer, const std::string& backend) {
  return {{"renderer", renderer},
          {"cores", std::thread::hardware_concurrency()},
          {"backend", backend},
          {"git", ECOVIEW_GIT_COMMIT}};
}

}  // namespace ecoview
