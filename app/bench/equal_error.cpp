#include "app/bench/equal_error.hpp"

#include <algorithm>
#include <cmath>

namespace ecoview {
namespace {

struct MapRun {
  double size, err, frame_ms, frame_ms_spread;
};

// The trade-off runs of one method on one scene, smallest map first.
std::vector<MapRun> map_runs(const std::vector<BenchRun>& runs, const std::string& scene, const std::string& method) {
  std::vector<MapRun> found;
  for (const BenchRun& run : runs) {
    if (run.params.value("sweep", "") != "tradeoff" || run.params.value("scene", "") != scene ||
        run.params.value("method", "") != method || run.params.value("shadow_size", 0) <= 0) {
      continue;
    }
    found.push_back({run.params["shadow_size"].get<double>(), run.figures["err"].get<double>(), run.figures["frame_ms"].get<double>(),
                     run.figures.value("frame_ms_spread", 0.0)});
  }
  std::sort(found.begin(), found.end(), [](const MapRun& a, const MapRun& b) { return a.size < b.size; });
  return found;
}

struct AtErr {
  double size, frame_ms, frame_ms_spread;
  const char* bound;
};

// The uniform map at `err`: between the two sizes whose errors enclose it (the first such pair
// from the smallest map), or the nearest end as a bound.
AtErr uniform_at(const std::vector<MapRun>& uniform, double err) {
  if (err >= uniform.front().err) return {uniform.front().size, uniform.front().frame_ms, uniform.front().frame_ms_spread, "at most"};
  for (std::size_t i = 0; i + 1 < uniform.size(); ++i) {
    const MapRun& a = uniform[i];
    const MapRun& b = uniform[i + 1];
    if (err > a.err || err < b.err || a.err == b.err) continue;
    // A zero error would have no logarithm: such a map already meets any level.
    if (b.err <= 0.0) return {b.size, b.frame_ms, b.frame_ms_spread, "at most"};
    const double t = (std::log(err) - std::log(a.err)) / (std::log(b.err) - std::log(a.err));
    auto log_lerp = [t](double x, double y) { return std::exp(std::log(x) + t * (std::log(y) - std::log(x))); };
    // The spread as the larger of the two it lies between: the time is read off both.
    return {log_lerp(a.size, b.size), log_lerp(a.frame_ms, b.frame_ms), std::max(a.frame_ms_spread, b.frame_ms_spread), "equal"};
  }
  return {uniform.back().size, uniform.back().frame_ms, uniform.back().frame_ms_spread, "at least"};
}

}  // namespace

std::vector<BenchRun> equal_error_runs(const std::vector<BenchRun>& runs, const std::string& scene, const std::string& method) {
  const std::vector<MapRun> uniform = map_runs(runs, scene, "uniform");
  std::vector<BenchRun> found;
  if (uniform.empty()) return found;
  for (const MapRun& m : map_runs(runs, scene, method)) {
    if (!(m.err > 0.0) || !(m.frame_ms > 0.0)) continue;  // an exact map has no level to match
    const AtErr u = uniform_at(uniform, m.err);
    BenchRun run;
    run.params = {{"sweep", "equal_err"}, {"scene", scene}, {"method", method}, {"shadow_size", static_cast<int>(m.size)},
                  {"bound", u.bound}};
    const double speedup = u.frame_ms / m.frame_ms;
    // A ratio's relative spread is about the sum of its two times' relative spreads.
    run.figures = {{"err", m.err}, {"equal_err_speedup", speedup},
                   {"equal_err_speedup_spread", speedup * (u.frame_ms_spread / u.frame_ms + m.frame_ms_spread / m.frame_ms)},
                   {"equal_err_texels", (u.size * u.size) / (m.size * m.size)}, {"uniform_size", u.size},
                   {"uniform_frame_ms", u.frame_ms}, {"uniform_frame_ms_spread", u.frame_ms_spread}};
    found.push_back(run);
  }
  return found;
}

}  // namespace ecoview
