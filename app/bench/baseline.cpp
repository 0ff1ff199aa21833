#include "app/bench/baseline.hpp"

#include <cmath>
#include <map>
#include <set>

namespace ecoview {
namespace {

nlohmann::json configuration(const BenchRun& run) {
  nlohmann::json params = run.params;
  params.erase("shadow_setup");
  return params;
}

bool is_spread(const std::string& figure) {
  return figure.size() >= spread_suffix.size() && figure.compare(figure.size() - spread_suffix.size(), std::string::npos, spread_suffix) == 0;
}

double spread_of(const BenchRun& run, const std::string& figure) {
  return run.figures.value(figure + std::string(spread_suffix), 0.0);
}

std::vector<FigureChange> figure_changes(const BenchRun& old_run, const BenchRun& new_run) {
  std::vector<FigureChange> changes;
  for (const auto& figure : new_run.figures.items()) {
    if (is_spread(figure.key()) || !old_run.figures.contains(figure.key())) continue;
    changes.push_back({configuration(new_run), figure.key(), old_run.figures[figure.key()].get<double>(), figure.value().get<double>(),
                       spread_of(old_run, figure.key()), spread_of(new_run, figure.key())});
  }
  return changes;
}

}  // namespace

bool FigureChange::flagged() const { return std::abs(new_value - old_value) > old_spread + new_spread; }

BaselineComparison compare_to_baseline(const std::vector<BenchRun>& baseline, const std::vector<BenchRun>& runs) {
  std::map<std::string, const BenchRun*> old_runs;
  for (const BenchRun& run : baseline) old_runs.emplace(configuration(run).dump(), &run);
  BaselineComparison comparison;
  std::set<std::string> matched;
  for (const BenchRun& run : runs) {
    const auto old_run = old_runs.find(configuration(run).dump());
    if (old_run == old_runs.end()) {
      ++comparison.runs_only_here;
      continue;
    }
    matched.insert(old_run->first);
    for (FigureChange& change : figure_changes(*old_run->second, run)) comparison.changes.push_back(std::move(change));
  }
  comparison.runs_only_in_baseline = static_cast<int>(old_runs.size() - matched.size());
  return comparison;
}

nlohmann::json baseline_section(const std::string& file, const BenchResults& baseline, const BaselineComparison& comparison) {
  nlohmann::json changes = nlohmann::json::array();
  for (const FigureChange& c : comparison.changes) {
    changes.push_back({{"params", c.params}, {"figure", c.figure}, {"old", c.old_value}, {"new", c.new_value},
                       {"old_spread", c.old_spread}, {"new_spread", c.new_spread}, {"flagged", c.flagged()}});
  }
  return {{"file", file}, {"git", baseline.machine.value("git", "unknown")}, {"quick", baseline.quick},
          {"rule", "flagged when |new - old| > old_spread + new_spread"}, {"runs_only_here", comparison.runs_only_here},
          {"runs_only_in_baseline", comparison.runs_only_in_baseline}, {"changes", changes}};
}

}  // namespace ecoview
