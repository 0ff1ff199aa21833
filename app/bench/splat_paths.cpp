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

}  // namespace

std::vector<BenchRun> measure_splat_paths(const Scene& scene, const std::string& scene_name, const RenderSettings& settings,
                                          int warmup, int frames) {
  const glm::ivec2 size(settings.width, settings.height);
  const glm::mat4 view_projection =
      scene.camera.projection(static_cast<float>(size.x) / static_cast<float>(size.y)) * scene.camera.view();
  const PointSamples samples(scene, settings.points_per_triangle, true);
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
