#pragma once
#include <chrono>

namespace ecoview {

using Clock = std::chrono::steady_clock;

// Wall time since `start`, in milliseconds.
inline double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace ecoview
