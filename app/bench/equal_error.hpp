#pragma once
#include "app/bench/results.hpp"

#include <string>
#include <vector>

namespace ecoview {

// What a warped map buys at equal accuracy (`equal_err_speedup`, docs/figures.md): for each size of
// `method`'s map on `scene` in the trade-off runs (sweep "tradeoff": params scene, method,
// shadow_size; figures err, frame_ms), the uniform map's frame time and size at the same `err`,
// interpolated between the uniform map's sizes linearly in log err against log size and log time.
// Figures: `equal_err_speedup` (the uniform map's frame_ms over the method's) and
// `equal_err_texels` (the uniform map's texels over the method's). Where the uniform map's sizes
// do not reach that err, the nearest size gives a bound: param "bound" is "at least" (its largest
// map is still worse) or "at most" (its smallest is already better), else "equal".
std::vector<BenchRun> equal_error_runs(const std::vector<BenchRun>& runs, const std::string& scene, const std::string& method);

}  // namespace ecoview
