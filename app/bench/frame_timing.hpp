#pragma once
#include "app/render/renderer.hpp"

#include <vector>

namespace ecoview {

// The median of some timings (0 for none).
double median(std::vector<double> v);

// frame_ms and its parts as DESIGN.md defines them: medians over `frames` frames after `warmup`
// frames, each frame finished with glFinish.
struct FrameTiming {
  double frame_ms = 0.0;
  double sample_ms = 0.0;
  double shadow_pass_ms = 0.0;
  double frame_pass_ms = 0.0;
  int frames = 0;
};

FrameTiming time_frames(Renderer& renderer, const shadow::Camera& camera, const shadow::Light& light, double t,
                        int warmup, int frames);

}  // namespace ecoview
