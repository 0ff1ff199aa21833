#include "app/bench/pareto_front.hpp"

#include <algorithm>
#include <map>
#include <string>

namespace ecoview {
namespace {

bool dominates(const TimeAndError& a, const TimeAndError& b) {
  return a.frame_ms <= b.frame_ms && a.err <= b.err && (a.frame_ms < b.frame_ms || a.err < b.err);
}

bool timed_sweep(const BenchRun& run) {
  const std::string sweep = run.params.value("sweep", "");
  return (sweep == "tradeoff" || sweep == "scenes") && run.figures.contains("frame_ms") && run.figures.contains("err");
}

}  // namespace

std::vector<std::size_t> pareto_front(const std::vector<TimeAndError>& points) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const bool beaten = std::any_of(points.begin(), points.end(), [&](const TimeAndError& p) { return dominates(p, points[i]); });
    if (!beaten) front.push_back(i);
  }
  std::stable_sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) { return points[a].frame_ms < points[b].frame_ms; });
  return front;
}

nlohmann::json pareto_fronts(const std::vector<BenchRun>& runs) {
  std::map<std::string, std::vector<const BenchRun*>> by_scene;
  for (const BenchRun& run : runs) {
    if (timed_sweep(run)) by_scene[run.params.value("scene", "")].push_back(&run);
  }
  nlohmann::json fronts = nlohmann::json::object();
  for (const auto& [scene, scene_runs] : by_scene) {
    std::vector<TimeAndError> points;
    for (const BenchRun* run : scene_runs) points.push_back({run->figures["frame_ms"].get<double>(), run->figures["err"].get<double>()});
    nlohmann::json front = nlohmann::json::array();
    for (std::size_t i : pareto_front(points)) {
      const BenchRun& run = *scene_runs[i];
      front.push_back({{"sweep", run.params["sweep"]}, {"method", run.params.value("method", "")},
                       {"shadow_size", run.params.value("shadow_size", 0)}, {"frame_ms", points[i].frame_ms}, {"err", points[i].err}});
    }
    fronts[scene] = front;
  }
  return fronts;
}

}  // namespace ecoview
