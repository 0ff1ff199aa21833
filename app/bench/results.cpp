#include "app/bench/results.hpp"

#include "app/errors.hpp"
#include "app/file_io.hpp"
#include "app/gl/context.hpp"
#include "app/scene/json_input.hpp"
#include "git_commit.hpp"

#include <fstream>
#include <limits>
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

// The compiler as its own macros name it at build time.
std::string compiler() {
#if defined(__clang__)
  return "clang " __clang_version__;
#elif defined(__GNUC__)
  return "gcc " __VERSION__;
#else
  return "unknown";
#endif
}

std::string field_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

// `value`, checked to be an object; `path` names it in the InputError otherwise.
const nlohmann::json& expect_object(const nlohmann::json& value, const std::string& file, const std::string& path) {
  if (!value.is_object()) JsonField(value, file, path).fail("expected an object");
  return value;
}

// object[key], which must be there.
const nlohmann::json& member(const nlohmann::json& object, const char* key, const std::string& file, const std::string& path) {
  const auto it = object.find(key);
  if (it == object.end()) JsonField(object, file, field_path(path, key)).fail("missing");
  return *it;
}

BenchRun read_run(const nlohmann::json& run, const std::string& file, const std::string& path) {
  expect_object(run, file, path);
  BenchRun read{expect_object(member(run, "params", file, path), file, field_path(path, "params")),
                expect_object(member(run, "figures", file, path), file, field_path(path, "figures"))};
  for (const auto& figure : read.figures.items()) {
    JsonField(figure.value(), file, field_path(path, "figures." + figure.key()))
        .number(std::numeric_limits<double>::lowest(), std::numeric_limits<double>::max());
  }
  return read;
}

// /proc/cpuinfo read to its end (/proc gives its files a size of 0, so pointgen::read_input_file,
// which reads no more than the size it finds, would read nothing); empty where there is none.
std::string proc_cpuinfo() {
  std::ifstream in("/proc/cpuinfo");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t");
  return first == std::string::npos ? "" : text.substr(first, text.find_last_not_of(" \t") - first + 1);
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
  nlohmann::json document = {{"machine", results.machine}, {"quick", results.quick}, {"runs", runs}};
  document.update(results.sections);
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

BenchResults read_results(const std::filesystem::path& file) {
  const std::string name = file.string();
  const nlohmann::json document = parse_json(read_named_file(file), name);
  expect_object(document, name, "");
  BenchResults results;
  results.machine = expect_object(member(document, "machine", name, ""), name, "machine");
  if (document.contains("quick")) results.quick = JsonField(document["quick"], name, "quick").boolean();
  const nlohmann::json& runs = member(document, "runs", name, "");
  if (!runs.is_array()) JsonField(runs, name, "runs").fail("expected an array");
  for (std::size_t i = 0; i < runs.size(); ++i) results.runs.push_back(read_run(runs[i], name, "runs[" + std::to_string(i) + "]"));
  return results;
}

nlohmann::json machine_info(const std::string& renderer, const std::string& backend) {
  return {{"cpu", cpu_model(proc_cpuinfo())},
          {"cores", std::thread::hardware_concurrency()},
          {"renderer", renderer},
          {"gl_version", gl_version()},
          {"backend", backend},
          {"compiler", compiler()},
          {"git", ECOVIEW_GIT_COMMIT}};
}

std::string cpu_model(const std::string& cpuinfo) {
  for (const char* key : {"model name", "Hardware", "Processor"}) {
    std::istringstream lines(cpuinfo);
    for (std::string line; std::getline(lines, line);) {
      const std::size_t colon = line.find(':');
      if (colon != std::string::npos && trimmed(line.substr(0, colon)) == key) return trimmed(line.substr(colon + 1));
    }
  }
  return "unknown";
}

}  // namespace ecoview
