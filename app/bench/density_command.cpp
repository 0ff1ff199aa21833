#include "app/bench/density_command.hpp"

#include "app/bench/charts.hpp"
#include "app/bench/density_figures.hpp"
#include "app/bench/frame_timing.hpp"
#include "app/bench/image_similarity.hpp"
#include "app/bench/results.hpp"
#include "app/bench/splat_paths.hpp"
#include "app/capture/png.hpp"
#include "app/cli/progress.hpp"
#include "app/errors.hpp"
#include "app/file_io.hpp"
#include "app/gl/context.hpp"
#include "app/scene/scene_file.hpp"
#include "pointgen/landscape/landscape_terrain.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace ecoview {
namespace {

namespace fs = std::filesystem;

struct Plan {
  std::vector<double> ks;
  std::vector<int> splats;
  std::vector<int> instance_counts;
  std::vector<double> landscape_plants;  // the shipped landscape's layers over areas holding these
  int polygon_instances_at_most;  // above it the stand is timed with points alone
  int warmup, frames, slow_frames;  // slow_frames: the polygon runs' and the largest stands', after 1 warm-up
  bool temporal_reference;  // the moving camera's change also with every plant as polygons (two slow frames)

  bool timed_as_polygons(int instances) const { return instances <= polygon_instances_at_most; }
};

// The reference of the quality runs: the polygons at this many samples a pixel each way.
constexpr int reference_samples = 4;

// k at half, at and at twice the default.
Plan plan_for(bool quick) {
  const double k = RenderSettings{}.k;
  if (quick) return {{k}, {2}, {300, 3000}, {1e6, 1e8}, 300, 1, 3, 1, false};
  // Under 10 minutes here. A polygon frame of 10^5 plants takes over a minute (one of 10^6 would
  // take ten); a point frame of 10^7 about 15 s.
  return {{0.5 * k, k, 2.0 * k}, {1, 2}, {1000, 10000, 100000, 1000000, 10000000}, {1e6, 1e7, 1e8, 1e9, 1e10}, 100000, 1, 5, 1, true};
}

// A flat stand of trees and bushes, `count` plants on 250 x 250 m, seen from its edge.
std::string stand_scene(int count) {
  std::ostringstream s;
  s << R"({"camera": {"position": [0, 12, 150], "target": [0, 4, 20], "fov_y_deg": 50, "near": 0.5, "far": 600},
          "lights": [{"type": "directional", "direction": [0.5, -0.7, -0.3]}],
          "objects": [{"type": "ecosystem", "seed": 11, "size": [250, 250], "terrain": {"relief": 0.5, "resolution": 16},
                       "plants": [)";
  const char* species[] = {"oak", "birch", "spruce", "hazel", "juniper"};
  for (int i = 0; i < 5; ++i) s << (i ? ", " : "") << R"({"species": ")" << species[i] << R"(", "count": )" << count / 5 << "}";
  s << "]}]}";
  return s.str();
}

// The shipped landscape's layers and terrain over a square holding about `plants`, seen from 12 m
// above its middle, looking along +x: the same view of the same ground whatever the area, but
// where the area ends short of it.
Scene landscape_of(double plants, double memory_budget_bytes) {
  const InputSource shipped = open_input("landscape", "scenes");
  nlohmann::json json = nlohmann::json::parse(shipped.text);
  const Scene full = load_scene(shipped, {memory_budget_bytes});
  const LandscapeSource& landscape = full.landscapes.at(0);
  const double per_m2 = full.landscape_plants / (static_cast<double>(landscape.spec.size.x) * landscape.spec.size.y);
  const double side = std::min(std::sqrt(plants / per_m2), static_cast<double>(pointgen::LandscapeSpec::max_size));
  json["objects"][0]["size"] = {side, side};
  const pointgen::LandscapeTerrain terrain(landscape.spec.terrain, landscape.spec.seed);
  json["camera"]["position"] = {0.0, terrain.height(0.0f, 0.0f) + 12.0, 0.0};
  json["camera"]["target"] = {200.0, terrain.height(200.0f, -60.0f), -60.0};
  return load_scene({"landscape", json.dump(), shipped.read_relative}, {memory_budget_bytes});
}

RenderedFrame grab(Renderer& renderer) { return {renderer.frame().read_color(), renderer.frame().read_depth()}; }

RenderedFrame render_once(const Scene& scene, const RenderSettings& settings) {
  Renderer renderer(scene, settings);
  renderer.render(scene.camera, scene.lights[0]);
  return grab(renderer);
}

Image8 difference(const Image8& a, const Image8& b) {
  Image8 d{a.width, a.height, 3, std::vector<std::uint8_t>(a.samples.size())};
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    d.samples[i] = static_cast<std::uint8_t>(std::min(255, 4 * std::abs(static_cast<int>(a.samples[i]) - b.samples[i])));
  }
  return d;
}

double changed_fraction(const Image8& a, const Image8& b) {
  std::size_t changed = 0;
  for (std::size_t i = 0; i < a.samples.size(); i += 3) {
    changed += a.samples[i] != b.samples[i] || a.samples[i + 1] != b.samples[i + 1] || a.samples[i + 2] != b.samples[i + 2];
  }
  return static_cast<double>(changed) / static_cast<double>(a.samples.size() / 3);
}

class DensityBench {
 public:
  DensityBench(const DensityOptions& o, const Plan& plan) : o_(o), plan_(plan), out_(o.run.out), base_(benchmark_settings(o.run)) {}

  // Quality against time: the scene's point-rendered objects, points against their polygons, with
  // the plants the sampler draws as polygons in both; and the whole frame, points and polygons at
  // one sample a pixel, each against the polygons at 4 × 4 samples a pixel resolved: the true
  // image, which the polygons miss too (sub-pixel leaves alias), so their figures are the floor
  // the points are held to.
  void quality(const Scene& scene, const std::string& scene_name, Progress& progress) {
    RenderSettings settings = base_;
    settings.method = shadow::Method::none;  // the sampler's quality alone; shadows are bench's
    settings.point_meshes_only = true;
    // The measures (the plants drawn as polygons, what the rest hides) are the CPU sampler's
    // choice, so the points measured against them are its points too.
    settings.gpu_sampler = false;
    // The whole scene with every plant in view as polygons, whatever k: one render of each serves
    // every k.
    RenderSettings whole = settings;
    whole.point_meshes_only = false;
    whole.points = false;
    RenderSettings fine = whole;
    fine.width *= reference_samples;
    fine.height *= reference_samples;
    if (const std::string refusal = driver_refusal(fine); !refusal.empty()) {
      throw InputError("--size: the quality runs' reference renders " + std::to_string(reference_samples) + " × " +
                       std::to_string(reference_samples) + " samples a pixel, and " + refusal.substr(refusal.find(": ") + 2));
    }
    const RenderedFrame polygons_in_scene = render_once(scene, whole);
    const Image8 reference = box_filtered(render_once(scene, fine).color, reference_samples);
    for (double k : plan_.ks) {
      settings.k = static_cast<float>(k);
      DensityRenders renders;
      renders.polygons_in_scene = polygons_in_scene;
      renders.reference = reference;
      settings.measure = RenderSettings::Measure::without_them;
      renders.occluders = render_once(scene, settings);
      settings.measure = RenderSettings::Measure::their_polygons;
      renders.polygons = render_once(scene, settings);
      for (int splat : plan_.splats) {
        settings.splat_size = splat;
        settings.measure = RenderSettings::Measure::off;
        Renderer points(scene, settings);
        const FrameTiming timing = time_frames(points, scene.camera, scene.lights[0], 0.0, plan_.warmup, plan_.frames);
        renders.points = grab(points);
        RenderSettings points_in_scene = settings;
        points_in_scene.point_meshes_only = false;
        renders.points_in_scene = render_once(scene, points_in_scene);
        const DensityFigures f = density_figures(renders, points.count_points_on(renders.polygons.depth));
        const FidelityFigures fidelity = fidelity_figures(renders);
        BenchRun run;
        run.params = {{"sweep", "quality"}, {"scene", scene_name}, {"k", k}, {"splat", splat}, {"geometry", "points"},
                      {"width", settings.width}, {"height", settings.height}, {"frames", timing.frames}};
        run.figures = {{"holes", f.holes}, {"psnr", fidelity.psnr}, {"ssim", fidelity.ssim}, {"psnr_polygons", fidelity.psnr_polygons},
                       {"ssim_polygons", fidelity.ssim_polygons}, {"pts_per_px", f.pts_per_px},
                       {"pts_per_px_cv", f.pts_per_px_cv}, {"pts_per_px_near", f.pts_per_px_near},
                       {"pts_per_px_middle", f.pts_per_px_middle}, {"pts_per_px_far", f.pts_per_px_far},
                       {"depth_nearest", f.third_depths[0]}, {"depth_middle_from", f.third_depths[1]},
                       {"depth_far_from", f.third_depths[2]}, {"depth_farthest", f.third_depths[3]},
                       {"points", points.stats().points}, {"triangles", points.stats().triangles},
                       {"frame_ms", timing.frame_ms}, {"sample_ms", timing.sample_ms}, {"host_ms", timing.host_ms}, {"frame_pass_ms", timing.frame_pass_ms},
                       {"sampler_mpts", timing.sample_ms > 0 ? 1e-3 * static_cast<double>(points.stats().points) / timing.sample_ms : 0.0}};
        results_.runs.push_back(run);
        if (k == base_.k && splat == base_.splat_size) save_images(renders);
        progress.step();
      }
    }
  }

  // Speed: the whole scene, shadows on, with points and with polygons.
  void speed(const Scene& scene, const std::string& scene_name, Progress& progress) {
    time_both_ways("speed", scene, scene_name, 0, progress);
  }

  // Scale: the same area with more and more plants.
  void scale(Progress& progress) {
    for (int count : plan_.instance_counts) {
      const Scene scene = load_scene({"stand", stand_scene(count), [](const std::string&) { return std::nullopt; }},
                                     {o_.run.memory_budget_gib * 1024.0 * 1024.0 * 1024.0});
      time_both_ways("scale", scene, "stand", count, progress);
    }
  }

  // Landscapes: the same view over areas holding 10^6 to 10^10 plants, made where the view needs
  // them; what the view costs should not grow with the area.
  void landscapes(Progress& progress) {
    for (double plants : plan_.landscape_plants) {
      const Scene scene = landscape_of(plants, o_.run.memory_budget_gib * 1024.0 * 1024.0 * 1024.0);
      Renderer renderer(scene, base_);
      const FrameTiming timing = time_frames(renderer, scene.camera, scene.lights[0], 0.0, plan_.warmup, plan_.frames);
      add_timing_run("landscape", "landscape", true, 0, timing, renderer.stats());
      BenchRun& run = results_.runs.back();
      run.params["plants"] = scene.landscape_plants;
      run.params["side_m"] = scene.landscapes.at(0).spec.size.x;
      const pointgen::LandscapePool::Stats& pool = renderer.stats().landscape;
      run.figures["pool_plants"] = pool.plants;
      run.figures["far_plants"] = pool.far_plants;
      run.figures["far_share"] = pool.far_share;
      progress.step();
    }
  }

  // Temporal noise: a still camera twice, and a camera moving slowly along the scene's view. The
  // exact renderer (every plant as polygons) changes pixels on that move too, as foliage finer
  // than a pixel moves under the pixel grid; `moving_noise` is what the points add to that, as
  // flicker (docs/figures.md) measures shadows against the reference.
  void temporal(const Scene& scene, const std::string& scene_name, Progress& progress) {
    shadow::Camera moved = scene.camera;
    const glm::vec3 step = 0.05f * moved.forward();  // 5 cm, a slow walk at 30 frames per second
    moved.position += step;
    moved.target += step;
    // The fraction of pixels that change from the scene's camera to `camera`.
    auto change = [&](Renderer& renderer, const shadow::Camera& camera) {
      renderer.render(scene.camera, scene.lights[0]);
      const Image8 first = renderer.frame().read_color();
      renderer.render(camera, scene.lights[0]);
      return changed_fraction(first, renderer.frame().read_color());
    };
    BenchRun run;
    run.params = {{"sweep", "temporal"}, {"scene", scene_name}, {"k", base_.k}, {"splat", base_.splat_size}};
    {
      Renderer points(scene, base_);  // released before the polygon renderer is made
      run.figures = {{"still_changed", change(points, scene.camera)}, {"moving_changed", change(points, moved)}};
    }
    if (plan_.temporal_reference) {
      RenderSettings all_polygons = base_;
      all_polygons.points = false;
      Renderer polygons(scene, all_polygons);
      const double reference = change(polygons, moved);
      run.figures["moving_changed_polygons"] = reference;
      run.figures["moving_noise"] = run.figures["moving_changed"].get<double>() - reference;
    }
    results_.runs.push_back(run);
    progress.step();
  }

  // Splat paths: the same points as one GL_POINTS draw, indirect draws and compute splats; and a
  // point's cost in the compute splat, from lists of up to several million points.
  void paths(const Scene& scene, const std::string& scene_name, Progress& progress) {
    const PointSamples samples(scene, base_.points_per_triangle, true);
    for (BenchRun& run : measure_splat_paths(scene, scene_name, samples, base_, plan_.warmup, plan_.frames)) results_.runs.push_back(std::move(run));
    for (BenchRun& run : measure_point_cost(scene, scene_name, samples, base_, plan_.warmup, plan_.frames)) results_.runs.push_back(std::move(run));
    progress.step();
  }

  void finish(const std::string& renderer_name) {
    std::ostringstream defaults;
    defaults << "k = " << base_.k << ", " << base_.splat_size << "-pixel splats";
    results_.machine = machine_info(renderer_name, o_.run.backend);
    results_.quick = o_.run.quick;
    write_results(out_, results_);
    draw_charts(out_, "density_charts.py");
    write_report(out_, "ecoview density", "",
                 "<h2>Charts</h2><img src=\"chart_quality.png\"><img src=\"chart_scale.png\"><img src=\"chart_thirds.png\">\n"
                 "<h2>Images (" + defaults.str() + ": the defaults)</h2>"
                 "<table><tr><th>reference: polygons, 4 × 4 samples a pixel</th><th>polygons, 1 sample a pixel</th><th>points</th></tr>"
                 "<tr><td><img src=\"images/reference.png\"></td><td><img src=\"images/polygons_in_scene.png\"></td>"
                 "<td><img src=\"images/points_in_scene.png\"></td></tr></table>\n"
                 "<table><tr><th>the objects drawn as points: polygons</th><th>points</th><th>difference × 4</th><th>measured pixels (holes red)</th></tr>"
                 "<tr><td><img src=\"images/polygons.png\"></td><td><img src=\"images/points.png\"></td>"
                 "<td><img src=\"images/difference.png\"></td><td><img src=\"images/coverage.png\"></td></tr></table>\n",
                 results_);
  }

 private:
  // Times the whole scene with points and, up to the plan's count, with polygons. Polygon frames,
  // and the point frames of the stands beyond that count, are slow: fewer of them.
  void time_both_ways(const char* sweep, const Scene& scene, const std::string& scene_name, int count, Progress& progress) {
    const bool with_polygons = plan_.timed_as_polygons(count);
    for (const bool points : {true, false}) {
      if (!points && !with_polygons) continue;
      RenderSettings settings = base_;
      settings.points = points;
      Renderer renderer(scene, settings);
      const bool slow = !points || !with_polygons;
      const FrameTiming timing = time_frames(renderer, scene.camera, scene.lights[0], 0.0, slow ? 1 : plan_.warmup,
                                             slow ? plan_.slow_frames : plan_.frames);
      add_timing_run(sweep, scene_name, points, count, timing, renderer.stats());
      progress.step();
    }
  }

  void add_timing_run(const char* sweep, const std::string& scene_name, bool points, int count, const FrameTiming& t,
                      const FrameStats& stats) {
    BenchRun run;
    run.params = {{"sweep", sweep}, {"scene", scene_name}, {"geometry", points ? "points" : "polygons"}, {"k", base_.k},
                  {"splat", base_.splat_size}, {"width", base_.width}, {"height", base_.height}, {"frames", t.frames}};
    if (count > 0) run.params["instances"] = count;
    run.figures = {{"frame_ms", t.frame_ms}, {"sample_ms", t.sample_ms}, {"host_ms", t.host_ms}, {"shadow_pass_ms", t.shadow_pass_ms},
                   {"frame_pass_ms", t.frame_pass_ms}, {"points", stats.points}, {"triangles", stats.triangles},
                   {"shadow_points", stats.shadow_points}, {"shadow_triangles", stats.shadow_triangles},
                   {"points_left_out", stats.points_left_out}};
    results_.runs.push_back(run);
  }

  void save_images(const DensityRenders& renders) {
    fs::create_directories(out_ / "images");
    const Image8& polygons = renders.polygons.color;
    const Image8& points = renders.points.color;
    write_file_atomically(out_ / "images" / "reference.png", encode_png(renders.reference));
    write_file_atomically(out_ / "images" / "polygons_in_scene.png", encode_png(renders.polygons_in_scene.color));
    write_file_atomically(out_ / "images" / "points_in_scene.png", encode_png(renders.points_in_scene.color));
    write_file_atomically(out_ / "images" / "polygons.png", encode_png(polygons));
    write_file_atomically(out_ / "images" / "points.png", encode_png(points));
    write_file_atomically(out_ / "images" / "difference.png", encode_png(difference(polygons, points)));
    write_file_atomically(out_ / "images" / "coverage.png", encode_png(coverage_map(renders)));
  }

  const DensityOptions& o_;
  Plan plan_;
  fs::path out_;
  RenderSettings base_;
  BenchResults results_;
};

}  // namespace

CLI::App* add_density_command(CLI::App& app, DensityOptions& o) {
  CLI::App* cmd = app.add_subcommand("density", "Point-density benchmark (k, splat size, plant count); writes a report");
  cmd->add_option("--scene", o.scene, std::string("Scene of the quality, speed and temporal runs (default: ") +
                                          default_scene_name + ")");
  add_benchmark_options(*cmd, o.run, "A few short runs, to check it works (80 s here; 4 min on busy cores)");
  return cmd;
}

int run_density(const DensityOptions& o) {
  parse_size(o.run.size);
  check_backend(o.run.backend);
  check_out_folder(o.run.out);
  const Scene scene = load_scene_option(o.scene, o.run.memory_budget_gib);
  const std::string scene_name = o.scene.empty() ? default_scene_name : o.scene;
  make_out_folder(o.run.out);

  const Plan plan = plan_for(o.run.quick);
  const std::unique_ptr<GlContext> context = create_headless_context(o.run.backend);
  DensityBench bench(o, plan);
  const auto with_polygons = std::ranges::count_if(plan.instance_counts, [&](int count) { return plan.timed_as_polygons(count); });
  Progress progress("density: run", plan.ks.size() * plan.splats.size() + 2 + plan.instance_counts.size() +
                                        static_cast<std::size_t>(with_polygons) + plan.landscape_plants.size() + 2);
  bench.quality(scene, scene_name, progress);
  bench.speed(scene, scene_name, progress);
  bench.scale(progress);
  bench.landscapes(progress);
  bench.temporal(scene, scene_name, progress);
  bench.paths(scene, scene_name, progress);
  progress.finish();
  bench.finish(context->description());
  std::cout << "density: wrote results.json, results.csv, charts and report.html to " << o.run.out << "\n";
  return 0;
}

}  // namespace ecoview
