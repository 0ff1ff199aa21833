#include "app/bench/frame_timing.hpp"

#include <algorithm>
#include <chrono>

namespace ecoview {
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

FrameTiming time_frames(Renderer& renderer, const shadow::Camera& camera, const shadow::Light& light, double t,
                        int warmup, int frames) {
  std::vector<double> wall, sample, shadow, frame;
  for (int i = 0; i < warmup + frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    renderer.render(camera, light, t);
    glFinish();
    if (i < warmup) continue;
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    sample.push_back(renderer.stats().sample_ms);
    shadow.push_back(renderer.stats().shadow_pass_ms);
    frame.push_back(renderer.stats().frame_pass_ms);
  }
  return {median(wall), median(sample), median(shadow), median(frame), frames};
}

}  // namespace ecoview
