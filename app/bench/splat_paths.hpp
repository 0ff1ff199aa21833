#pragma once
#include "app/bench/results.hpp"
#include "app/render/renderer.hpp"

#include <string>
#include <vector>

namespace ecoview {

// The candidate ways to splat one-pixel points, timed on the same points: the point-mesh instances
// the sampler picks in the scene camera's view (`samples`: the scene's, made with the settings'
// points_per_triangle) (all drawn as points, whatever the polygon choice),
// into a settings.width x settings.height target, depth tested.
//  - "gl_points": one glDrawArrays(GL_POINTS), each vertex finding its instance by binary search;
//  - "indirect": glMultiDrawArraysIndirect(GL_POINTS), one command per instance;
//  - "compute": PointSplat, nearest depth by atomicMin, then the nearest point per pixel.
// Each run: params {sweep "paths", scene, path, width, height, frames}, figures {points, ms,
// gpu_ms, mpts_per_s = points / ms}; medians of `frames` frames after `warmup`, target clear
// included. `ms` is wall time from glFinish to glFinish around the draw alone: llvmpipe's
// GL_TIME_ELAPSED (`gpu_ms`) misses the vertex work of small draws (0.09 ms against 16 ms of wall
// time for 0.1 M points) and half the compute splat's time. Needs a current GL context.
std::vector<BenchRun> measure_splat_paths(const Scene& scene, const std::string& scene_name, const PointSamples& samples,
                                          const RenderSettings& settings, int warmup, int frames);

// A point's cost in the frame's compute splat (PointSplat passes 1 and 2, the settings' splat
// size): the same view's points with k and the point-or-polygon break-even at each of
// point_cost_scales times the settings' (the same plants, up to several million points), timed as
// above. A run per scale: params {sweep "point_cost", scene, scale, splat, width, height, frames},
// figures {points, ms}; then one with scale "fit": figures {ns_per_point, fixed_ms}, the slope and
// intercept of the least-squares line of ms against points.
inline constexpr int point_cost_scales[] = {1, 2, 3, 4};
std::vector<BenchRun> measure_point_cost(const Scene& scene, const std::string& scene_name, const PointSamples& samples,
                                         const RenderSettings& settings, int warmup, int frames);

}  // namespace ecoview
