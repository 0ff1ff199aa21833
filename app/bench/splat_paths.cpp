#include "app/bench/splat_paths.hpp"

#include "app/bench/frame_timing.hpp"
#include "app/bench/point_raster.hpp"

#include <algorithm>
#include <chrono>
#include <functional>

namespace ecoview {
namespace {

struct PathTime {
  double ms = 0.0;      // wall clock from glFinish to glFinish around the draw alone
  double gpu_ms = 0.0;  // GL_TIME_ELAPSED
};

// Median times of `draw`, in milliseconds, over `frames` calls after `warmup` untimed ones.
PathTime time_path(int warmup, int frames, const std::function<void()>& draw) {
  const gl::Query timer(GL_TIME_ELAPSED);
  std::vector<double> wall, gpu;
  for (int i = 0; i < warmup + frames; ++i) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    glBeginQuery(GL_TIME_ELAPSED, timer.name());
    draw();
    glEndQuery(GL_TIME_ELAPSED);
    glFinish();
    const auto end = std::chrono::steady_clock::now();
    GLuint64 nanoseconds = 0;
    glGetQueryObjectui64v(timer.name(), GL_QUERY_RESULT, &nanoseconds);
    if (i < warmup) continue;
    wall.push_back(std::chrono::duration<double, std::milli>(end - start).count());
    gpu.push_back(static_cast<double>(nanoseconds) * 1e-6);
  }
  return {median(wall), median(gpu)};
}

glm::mat4 camera_view_projection(const Scene& scene, glm::ivec2 size) {
  return scene.camera.projection(static_cast<float>(size.x) / static_cast<float>(size.y)) * scene.camera.view();
}

// The least-squares line through (x, y): y = intercept + slope x.
struct Line {
  double slope = 0.0, intercept = 0.0;
};
Line fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const auto n = static_cast<double>(x.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double spread = n * sxx - sx * sx;
  if (spread <= 0.0) return {};
  const double slope = (n * sxy - sx * sy) / spread;
  return {slope, (sy - slope * sx) / n};
}

}  // namespace

std::vector<BenchRun> measure_point_cost(const Scene& scene, const std::string& scene_name, const PointSamples& samples,
                                         const RenderSettings& settings, int warmup, int frames) {
  const glm::ivec2 size(settings.width, settings.height);
  const glm::mat4 view_projection = camera_view_projection(scene, size);
  const auto params = [&](const nlohmann::json& scale) {
    return nlohmann::json{{"sweep", "point_cost"}, {"scene", scene_name}, {"scale", scale}, {"splat", settings.splat_size},
                          {"width", size.x}, {"height", size.y}, {"frames", frames}};
  };
  std::vector<BenchRun> runs;
  std::vector<double> points, ms;
  for (int scale : point_cost_scales) {
    // k and the point-or-polygon break-even scaled alike: the same plants, scale times their points
    // (up to their lists).
    RenderSettings denser = settings;
    denser.k *= static_cast<float>(scale);
    denser.points_per_triangle *= static_cast<float>(scale);
    const pointgen::SampledFrame selection =
        pointgen::sample_view(sampler_view(scene.camera, denser, {view_projection}), scene.groups, samples.meshes());
    PointSplat splat(size);
    splat.upload(selection.points, scene.groups, samples);
    std::size_t count = 0;
    for (const pointgen::PointDraw& d : selection.points) count += d.count;
    const PathTime t = time_path(warmup, frames, [&] { splat.splat(view_projection, settings.splat_size, 0.0f); });
    points.push_back(static_cast<double>(count));
    ms.push_back(t.ms);
    BenchRun run;
    run.params = params(scale);
    run.figures = {{"points", count}, {"ms", t.ms}};
    runs.push_back(run);
  }
  const Line line = fit_line(points, ms);
  BenchRun fit;
  fit.params = params("fit");
  fit.figures = {{"ns_per_point", line.slope * 1e6}, {"fixed_ms", line.intercept}};
  runs.push_back(fit);
  return runs;
}

std::vector<BenchRun> measure_splat_paths(const Scene& scene, const std::string& scene_name, const PointSamples& samples,
                                          const RenderSettings& settings, int warmup, int frames) {
  const glm::ivec2 size(settings.width, settings.height);
  const glm::mat4 view_projection = camera_view_projection(scene, size);
  const pointgen::SampledFrame selection =
      pointgen::sample_view(sampler_view(scene.camera, settings, {view_projection}), scene.groups, samples.meshes());

  PointRaster raster(size);
  raster.upload(selection.points, scene.groups, samples);
  PointSplat splat(size);
  splat.upload(selection.points, scene.groups, samples);
  const std::pair<const char*, std::function<void()>> paths[] = {
      {"gl_points", [&] { raster.draw_all(view_projection); }},
      {"indirect", [&] { raster.draw_indirect(view_projection); }},
      {"compute", [&] { splat.splat(view_projection, 1, 0.0f); }},
  };
  std::vector<BenchRun> runs;
  const auto points = static_cast<double>(raster.point_count());
  for (const auto& [name, draw] : paths) {
    const PathTime t = time_path(warmup, frames, draw);
    BenchRun run;
    run.params = {{"sweep", "paths"}, {"scene", scene_name}, {"path", name}, {"width", size.x}, {"height", size.y},
                  {"frames", frames}};
    run.figures = {{"points", raster.point_count()}, {"ms", t.ms}, {"gpu_ms", t.gpu_ms},
                   {"mpts_per_s", t.ms > 0.0 ? 1e-3 * points / t.ms : 0.0}};
    runs.push_back(run);
  }
  return runs;
}

}  // namespace ecoview
