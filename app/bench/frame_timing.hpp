#pragma once
#include "app/render/renderer.hpp"

#include <vector>

namespace ecoview {

// The median of some timings (0 for none).
double median(std::vector<double> v);

// Their interquartile range (0 for fewer than two): how far one time's repeats stray from one
// another, which a median taken from them may do too from one run to the next.
double interquartile_range(std::vector<double> v);

// frame_ms and its parts as docs/figures.md defines them: medians over `frames` frames after `warmup`
// frames, each frame finished with glFinish.
struct FrameTiming {
  double frame_ms = 0.0;
  double sample_ms = 0.0;
  double host_ms = 0.0;
  double shadow_pass_ms = 0.0;
  double frame_pass_ms = 0.0;
  int frames = 0;
  // The interquartile range of each time's repeats over the timed frames: the spread that bench
  // --baseline allows a time before it flags a change.
  double frame_ms_spread = 0.0;
  double sample_ms_spread = 0.0;
  double host_ms_spread = 0.0;
  double shadow_pass_ms_spread = 0.0;
  double frame_pass_ms_spread = 0.0;
};

FrameTiming time_frames(Renderer& renderer, const shadow::Camera& camera, const shadow::Light& light, double t,
                        int warmup, int frames);

// The same for several renderers of one view, their frames taken in turn (one of each, then the
// next of each), so that a slow spell of a shared machine falls on all of them alike and their
// ratios hold; one timing per renderer.
std::vector<FrameTiming> time_frames_in_turn(const std::vector<Renderer*>& renderers, const shadow::Camera& camera,
                                             const shadow::Light& light, double t, int warmup, int frames);

}  // namespace ecoview
