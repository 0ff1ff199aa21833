#include "app/bench/frame_timing.hpp"

#include <algorithm>
#include <chrono>

namespace ecoview {
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The quartiles as the medians of the lower and upper halves (the middle value of an odd count
// left out of both), so that the spread is a median's kind of figure too.
double interquartile_range(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const auto half = static_cast<std::ptrdiff_t>(v.size() / 2);
  return median(std::vector<double>(v.end() - half, v.end())) - median(std::vector<double>(v.begin(), v.begin() + half));
}

FrameTiming time_frames(Renderer& renderer, const shadow::Camera& camera, const shadow::Light& light, double t,
                        int warmup, int frames) {
  return time_frames_in_turn({&renderer}, camera, light, t, warmup, frames).front();
}

std::vector<FrameTiming> time_frames_in_turn(const std::vector<Renderer*>& renderers, const shadow::Camera& camera,
                                             const shadow::Light& light, double t, int warmup, int frames) {
  struct Times {
    std::vector<double> wall, sample, host, shadow, frame;
  };
  std::vector<Times> times(renderers.size());
  for (int i = 0; i < warmup + frames; ++i) {
    for (std::size_t r = 0; r < renderers.size(); ++r) {
      const auto start = std::chrono::steady_clock::now();
      renderers[r]->render(camera, light, t);
      glFinish();
      if (i < warmup) continue;
      const FrameStats& stats = renderers[r]->stats();
      times[r].wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      times[r].sample.push_back(stats.sample_ms);
      times[r].host.push_back(stats.host_ms);
      times[r].shadow.push_back(stats.shadow_pass_ms);
      times[r].frame.push_back(stats.frame_pass_ms);
    }
  }
  std::vector<FrameTiming> timings;
  for (Times& m : times) {
    timings.push_back({median(m.wall), median(m.sample), median(m.host), median(m.shadow), median(m.frame), frames,
                       interquartile_range(m.wall), interquartile_range(m.sample), interquartile_range(m.host),
                       interquartile_range(m.shadow), interquartile_range(m.frame)});
  }
  return timings;
}

}  // namespace ecoview
