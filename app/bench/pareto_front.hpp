#pragma once
#include "app/bench/results.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <vector>

namespace ecoview {

// The methods worth their cost: a scene's runs that no other run beats in both frame time and
// error. Bench's report opens with them, and the trade-off chart draws them as a line.

struct TimeAndError {
  double frame_ms = 0.0;
  double err = 0.0;
};

// The indices of the points no other point dominates (one at most as slow and at most as wrong,
// and better in one of the two), in order of time. Points equal in both are all kept: neither
// beats the other.
std::vector<std::size_t> pareto_front(const std::vector<TimeAndError>& points);

// For each scene of the timed sweeps (tradeoff and scenes), the runs on its front in order of
// time: {scene: [{"sweep", "method", "shadow_size", "frame_ms", "err"}, ...]}.
nlohmann::json pareto_fronts(const std::vector<BenchRun>& runs);

}  // namespace ecoview
