#include "app/bench/bench_command.hpp"

#include "app/bench/baseline.hpp"
#include "app/bench/bench_report.hpp"
#include "app/bench/charts.hpp"
#include "app/bench/crop.hpp"
#include "app/bench/equal_error.hpp"
#include "app/bench/measured_view.hpp"
#include "app/bench/paper_suite.hpp"
#include "app/bench/pareto_front.hpp"
#include "app/bench/frame_timing.hpp"
#include "app/bench/results.hpp"
#include "app/bench/shadow_figures.hpp"
#include "app/capture/png.hpp"
#include "app/cli/progress.hpp"
#include "app/errors.hpp"
#include "app/file_io.hpp"
#include "app/gl/context.hpp"
#include "app/reference/exact_visibility.hpp"
#include "app/scene/camera_path.hpp"
#include "app/scene/scene_file.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

namespace ecoview {
namespace {

namespace fs = std::filesystem;

// The maps timed for a light: those with a setup of their own for it, and `auto`.
std::vector<shadow::Method> map_methods(shadow::LightType light) {
  std::vector<shadow::Method> methods = shadow::map_techniques(light);
  methods.push_back(shadow::Method::automatic);
  return methods;
}
const std::vector<shadow::Method> directional_methods = map_methods(shadow::LightType::directional);
const std::vector<shadow::Method> point_methods = map_methods(shadow::LightType::point);

// The methods with no map size to sweep: the masks of the frame's lit pixels (the exact ones and
// the hybrid, whose map only finds where its volumes count), and the virtual paged map.
std::vector<shadow::Method> unsized_methods() {
  std::vector<shadow::Method> methods;
  for (const shadow::Technique& t : shadow::techniques()) {
    if (t.lookup == shadow::Lookup::mask || t.lookup == shadow::Lookup::pages) methods.push_back(t.method);
  }
  return methods;
}

// The maps flown along the big scene's path: those for its directional light, and the paged ones.
std::vector<shadow::Method> flight_methods() {
  std::vector<shadow::Method> methods = directional_methods;
  for (const shadow::Technique& t : shadow::techniques()) {
    if (t.lookup == shadow::Lookup::pages) methods.push_back(t.method);
  }
  return methods;
}

// What a run does. The scenes: `field` (posts over a 400 m plane, its 13 lights turning 0°–180°
// from the view in 15° steps; 90° is the PSM paper's favourable case) and the ecosystem with its
// path; --quick puts the courtyard in the ecosystem's place.
struct Plan {
  std::vector<int> sizes;        // shadow-map sizes of the trade-off sweep
  int warmup, frames;            // timed frames per configuration on the field
  int big_warmup, big_frames;    // the same on the big scene
  int angle_step;                // stability: every angle_step-th field light
  std::vector<float> crossing;   // metres along the view from the camera plane
  int flight_frames;             // frames spread over the big scene's path
  int flicker_frames;            // consecutive frames (30 per second) for flicker
  std::string big_scene;
  std::vector<std::string> polygon_scenes;  // every method at one map size
  int scene_frames;              // timed frames a method there, after one
};

Plan plan_for(bool quick) {
  if (quick) return {{512, 1024}, 1, 1, 1, 1, 6, {-5.0f, 5.0f}, 2, 2, "courtyard", {"chess"}, 1};
  // The field's frames as docs/bench.md says they are timed (20 after 3); the big scene's take seconds each.
  return {{512, 1024, 2048, 4096, 8192}, 3, 20, 1, 2, 1, {-20.0f, -8.0f, -3.0f, -1.0f, -0.25f, 0.25f, 1.0f, 3.0f, 8.0f, 20.0f},
          6, 4, "ecosystem", {"courtyard", "chess", "street"}, 5};
}

constexpr int favourable_light = 6;       // field: 90° between light and view
constexpr int crop_size = 1024;           // the trade-off map size whose frames are cropped
constexpr int crop_magnification = 3;     // each frame pixel of a crop drawn as 3 × 3


class ShadowBench {
 public:
  ShadowBench(const BenchOptions& o, const Plan& plan, std::optional<BenchResults> baseline)
      : o_(o), plan_(plan), out_(o.run.out), base_(benchmark_settings(o.run)), baseline_(std::move(baseline)) {
    fs::create_directories(out_ / "images");
  }

  // Speed against accuracy: every method at every map size, the methods of one size timed in turn.
  void trade_off(const MeasuredView& view, const std::string& scene_name, bool small, Progress& progress) {
    const std::vector<shadow::Method>& methods =
        view.light.type == shadow::LightType::directional ? directional_methods : point_methods;
    for (int size : plan_.sizes) {
      if (!driver_refusal(for_scene(settings(methods.front(), size), view.scene)).empty()) {  // where the driver allows
        for (std::size_t m = 0; m < methods.size(); ++m) progress.step();
        continue;
      }
      std::vector<std::unique_ptr<Renderer>> renderers;
      std::vector<Renderer*> timed;
      for (shadow::Method method : methods) {
        renderers.push_back(std::make_unique<Renderer>(view.scene, for_scene(settings(method, size), view.scene)));
        timed.push_back(renderers.back().get());
      }
      const std::vector<FrameTiming> timings =
          time_frames_in_turn(timed, view.camera, view.light, view.t, small ? plan_.warmup : plan_.big_warmup,
                              small ? plan_.frames : plan_.big_frames);
      for (std::size_t m = 0; m < methods.size(); ++m) {
        BenchRun run = measure_view(*renderers[m], view, timings[m]);
        run.params.update({{"sweep", "tradeoff"}, {"scene", scene_name}, {"method", shadow::technique(methods[m]).name}, {"shadow_size", size}});
        results_.runs.push_back(run);
        if (size == crop_size) crop(*renderers[m], scene_name, shadow::technique(methods[m]).name);
        progress.step();
      }
    }
    for (shadow::Method method : methods) {
      if (method == shadow::Method::uniform) continue;
      for (BenchRun& run : equal_error_runs(results_.runs, scene_name, shadow::technique(method).name)) results_.runs.push_back(std::move(run));
    }
    // The exact methods and the paged map are points on the chart too: what exactness costs here,
    // and what the frame's own pages do, one frame each.
    for (shadow::Method unsized : unsized_methods()) {
      Renderer renderer(view.scene, for_scene(settings(unsized, 0), view.scene));
      BenchRun run = measure_view(renderer, view, time_frames(renderer, view.camera, view.light, view.t, 0, 1));
      run.params.update({{"sweep", "tradeoff"}, {"scene", scene_name}, {"method", shadow::technique(unsized).name}, {"shadow_size", 0}});
      results_.runs.push_back(run);
      crop(renderer, scene_name, shadow::technique(unsized).name);
    }
    progress.step();
  }

  // A polygon scene at the crop size: every method for its first light and the exact ones, timed
  // in turn, so that each technique stands beside the one it improves on (hybrid beside the
  // volumes, a silhouette map beside its map) where polygons cast every shadow.
  void polygon_scene(const Scene& scene, const std::string& scene_name, Progress& progress) {
    ExactVisibility exact(scene.meshes, scene.groups);
    const MeasuredView view{scene, exact, scene.camera, scene.lights[0]};
    std::vector<shadow::Method> methods = view.light.type == shadow::LightType::directional ? directional_methods : point_methods;
    for (shadow::Method m : unsized_methods()) methods.push_back(m);
    std::vector<std::unique_ptr<Renderer>> renderers;
    std::vector<Renderer*> timed;
    for (shadow::Method method : methods) {
      renderers.push_back(std::make_unique<Renderer>(scene, for_scene(settings(method, crop_size), scene)));
      timed.push_back(renderers.back().get());
    }
    const std::vector<FrameTiming> timings = time_frames_in_turn(timed, view.camera, view.light, view.t, 1, plan_.scene_frames);
    for (std::size_t m = 0; m < methods.size(); ++m) {
      BenchRun run = measure_view(*renderers[m], view, timings[m]);
      run.params.update({{"sweep", "scenes"}, {"scene", scene_name}, {"method", shadow::technique(methods[m]).name}, {"shadow_size", crop_size}});
      results_.runs.push_back(run);
      crop(*renderers[m], scene_name, shadow::technique(methods[m]).name);
      progress.step();
    }
  }

  // Stability against the light direction: the field's lights from along the view (0°) through
  // across it (90°) to into the camera (180°).
  void stability(const Scene& field, ExactVisibility& exact, Progress& progress) {
    for (std::size_t l = 0; l < field.lights.size(); l += static_cast<std::size_t>(plan_.angle_step)) {
      for (shadow::Method method : directional_methods) {
        Renderer renderer(field, for_scene(settings(method, crop_size), field));
        BenchRun run = measure_view(renderer, {field, exact, field.camera, field.lights[l]});
        run.params.update({{"sweep", "stability"}, {"scene", "field"}, {"method", shadow::technique(method).name},
                           {"shadow_size", crop_size}, {"light_view_deg", field_light_step_deg * static_cast<float>(l)}});
        results_.runs.push_back(run);
        progress.step();
      }
    }
  }

  // A point light 8 m above the camera's eye level, moved along the view through the camera
  // plane: in front it stays a point light in post-perspective space, behind it is inverted.
  void crossing(const Scene& field, ExactVisibility& exact, Progress& progress) {
    for (float offset : plan_.crossing) {
      shadow::Light lamp;
      lamp.type = shadow::LightType::point;
      lamp.position = field.camera.position + offset * field.camera.forward() + glm::vec3(0.0f, 8.0f, 0.0f);
      for (shadow::Method method : point_methods) {
        Renderer renderer(field, for_scene(settings(method, crop_size), field));
        BenchRun run = measure_view(renderer, {field, exact, field.camera, lamp});
        run.params.update({{"sweep", "crossing"}, {"scene", "field"}, {"method", shadow::technique(method).name},
                           {"shadow_size", crop_size}, {"light_offset_m", offset}});
        results_.runs.push_back(run);
        progress.step();
      }
    }
  }

  // The big scene along its path: the error per frame, and flicker over consecutive frames.
  void flythrough(const Scene& scene, ExactVisibility& exact, const CameraPath& path, const std::string& scene_name,
                  Progress& progress) {
    const shadow::Light& light = scene.lights[0];
    for (shadow::Method method : flight_methods()) {
      Renderer renderer(scene, for_scene(settings(method, crop_size), scene));
      for (int f = 0; f < plan_.flight_frames; ++f) {
        const double t = path.duration() * f / std::max(1, plan_.flight_frames - 1);
        BenchRun run = measure_view(renderer, {scene, exact, path.at(t, scene.camera), light, t});
        run.params.update({{"sweep", "flythrough"}, {"scene", scene_name}, {"method", shadow::technique(method).name},
                           {"shadow_size", crop_size}, {"frame", f}, {"t", t}});
        results_.runs.push_back(run);
        progress.step();
      }
      results_.runs.push_back(flicker(renderer, scene, exact, path, scene_name, method));
      progress.step();
    }
  }

  void finish(const std::string& renderer_name) {
    results_.machine = machine_info(renderer_name, o_.run.backend);
    results_.quick = o_.run.quick;
    results_.sections["pareto_front"] = pareto_fronts(results_.runs);
    if (baseline_) {
      results_.sections["baseline"] = baseline_section(o_.baseline, *baseline_, compare_to_baseline(baseline_->runs, results_.runs));
    }
    write_results(out_, results_);
    draw_charts(out_, "bench_charts.py");
    write_report(out_, "ecoview bench", summary(), report_body(), results_);
  }

 private:
  RenderSettings settings(shadow::Method method, int shadow_size) const {
    RenderSettings s = base_;
    s.method = method;
    if (shadow_size > 0) s.shadow_size = shadow_size;
    return s;
  }

  // flicker (docs/figures.md): the mean share of pixels whose shadow state changes between consecutive
  // frames at 30 per second from the middle of the path, less the same for the reference.
  BenchRun flicker(Renderer& renderer, const Scene& scene, ExactVisibility& exact, const CameraPath& path,
                   const std::string& scene_name, shadow::Method method) {
    const double start = 0.5 * path.duration();
    Image8 last_frame, last_reference;
    double changed = 0.0, reference_changed = 0.0, unlike_reference = 0.0;
    renderer.render(path.at(start, scene.camera), scene.lights[0], start);  // a last frame for the PSM
    for (int f = 0; f < plan_.flicker_frames; ++f) {
      const double t = start + f / 30.0;
      const MeasuredView view{scene, exact, path.at(t, scene.camera), scene.lights[0], t};
      renderer.render(view.camera, view.light, t);
      const Image<float> depth = renderer.frame().read_depth();
      Image8 frame = renderer.frame().read_visibility(), exact = exact_frame(renderer, view, depth);
      if (f > 0) {
        changed += changed_shadow(last_frame, frame, depth);
        reference_changed += changed_shadow(last_reference, exact, depth);
        unlike_reference += temporal_err(last_frame, frame, last_reference, exact, depth);
      }
      last_frame = std::move(frame);
      last_reference = std::move(exact);
    }
    const double pairs = std::max(1, plan_.flicker_frames - 1);
    BenchRun run;
    run.params = {{"sweep", "flicker"}, {"scene", scene_name}, {"method", shadow::technique(method).name}, {"shadow_size", crop_size},
                  {"frames", plan_.flicker_frames}, {"t", start}};
    run.figures = {{"flicker", (changed - reference_changed) / pairs}, {"changed", changed / pairs},
                   {"reference_changed", reference_changed / pairs}, {"temporal_err", unlike_reference / pairs}};
    return run;
  }

  // A quarter of the frame's width and height, magnified so that one texel's stair step is seen:
  // for every method of a scene the place where its first method's shadows have the most edges.
  void crop(const Renderer& renderer, const std::string& scene_name, const std::string& method) {
    const Image8 color = renderer.frame().read_color();
    if (!crop_rects_.count(scene_name)) {
      crop_rects_[scene_name] = busiest_shadow_edges(renderer.frame().read_visibility(), color.width / 4, color.height / 4);
    }
    write_file_atomically(out_ / "images" / ("crop_" + scene_name + "_" + method + ".png"),
                          encode_png(magnified_crop(color, crop_rects_[scene_name], crop_magnification)));
    crops_[scene_name].push_back(method);
  }

  std::string summary() const {
    const auto baseline = results_.sections.find("baseline");
    return pareto_summary_html(results_.sections["pareto_front"]) + (baseline == results_.sections.end() ? "" : baseline_html(*baseline));
  }

  std::string report_body() const {
    std::ostringstream html;
    html << "<h2>Speed against accuracy</h2><img src=\"chart_tradeoff.png\">\n"
         << "<h2>The uniform map at each method's error</h2><img src=\"chart_equal_err.png\">\n"
         << "<h2>The polygon scenes, every method at " << crop_size << "²</h2><img src=\"chart_scenes.png\">\n"
         << "<h2>Stability</h2><img src=\"chart_stability.png\">\n"
         << "<h2>Flythrough</h2><img src=\"chart_flythrough.png\">\n"
         << crops_html(crops_, crop_size);
    return html.str();
  }

  const BenchOptions& o_;
  Plan plan_;
  fs::path out_;
  RenderSettings base_;
  std::optional<BenchResults> baseline_;
  BenchResults results_;
  std::map<std::string, std::vector<std::string>> crops_;
  std::map<std::string, PixelRect> crop_rects_;  // where each scene's crops are taken
};

}  // namespace

CLI::App* add_bench_command(CLI::App& app, BenchOptions& o) {
  CLI::App* cmd = app.add_subcommand("bench", "Shadow-method benchmark, speed against accuracy; writes a report");
  add_benchmark_options(*cmd, o.run, "Small scenes, few configurations (25 s here; 1-1.5 min on busy cores)");
  cmd->add_option("--suite", o.suite, "methods (speed against accuracy) or paper (the PSM paper's figures)")
      ->capture_default_str();
  cmd->add_option("--baseline", o.baseline, "An earlier run's results.json: each change, flagged beyond the spread");
  return cmd;
}

int run_bench(const BenchOptions& o) {
  parse_size(o.run.size);
  check_backend(o.run.backend);
  if (o.suite != "methods" && o.suite != "paper") throw InputError("--suite: expected methods or paper, got '" + o.suite + "'");
  if (o.suite == "paper") {
    if (!o.baseline.empty()) throw InputError("--baseline: compares the methods suite's runs; the paper suite has none to compare");
    run_paper_suite(o.run);
    return 0;
  }
  // The baseline is read first: a wrong file is refused before minutes of runs.
  std::optional<BenchResults> baseline;
  if (!o.baseline.empty()) baseline = read_results(o.baseline);
  // A quick run has other scenes, sizes and frame counts than a full one: no run would match.
  if (baseline && baseline->quick != o.run.quick) {
    throw InputError("--baseline: " + o.baseline + ": quick: the file holds a " + (baseline->quick ? "quick" : "full") +
                     " run and this one is " + (o.run.quick ? "quick" : "full") + "; compare runs of one kind");
  }
  make_out_folder(o.run.out);
  const Plan plan = plan_for(o.run.quick);
  const Scene field = load_scene_option("field", o.run.memory_budget_gib);
  const Scene big = load_scene_option(plan.big_scene, o.run.memory_budget_gib);
  const CameraPath path = CameraPath::load(open_input(plan.big_scene, "paths"));

  const std::unique_ptr<GlContext> context = create_headless_context(o.run.backend);
  ExactVisibility field_exact(field.meshes, field.groups), big_exact(big.meshes, big.groups);
  ShadowBench bench(o, plan, std::move(baseline));
  const std::size_t angles = (field.lights.size() + static_cast<std::size_t>(plan.angle_step) - 1) / static_cast<std::size_t>(plan.angle_step);
  const std::size_t methods = directional_methods.size(), point_light_methods = point_methods.size();
  std::vector<Scene> polygon_scenes;
  std::size_t polygon_scene_runs = 0;
  for (const std::string& name : plan.polygon_scenes) {
    polygon_scenes.push_back(load_scene_option(name, o.run.memory_budget_gib));
    const bool directional = polygon_scenes.back().lights.at(0).type == shadow::LightType::directional;
    polygon_scene_runs += (directional ? methods : point_light_methods) + unsized_methods().size();
  }
  Progress progress("bench: run", 2 * (methods * plan.sizes.size() + 1) + polygon_scene_runs + angles * methods +
                                      plan.crossing.size() * point_light_methods +
                                      flight_methods().size() * static_cast<std::size_t>(plan.flight_frames + 1));
  bench.trade_off({field, field_exact, field.camera, field.lights[favourable_light]}, "field", true, progress);
  bench.trade_off({big, big_exact, big.camera, big.lights[0]}, plan.big_scene, false, progress);
  for (std::size_t i = 0; i < polygon_scenes.size(); ++i) bench.polygon_scene(polygon_scenes[i], plan.polygon_scenes[i], progress);
  bench.stability(field, field_exact, progress);
  bench.crossing(field, field_exact, progress);
  bench.flythrough(big, big_exact, path, plan.big_scene, progress);
  progress.finish();
  bench.finish(context->description());
  std::cout << "bench: wrote results.json, results.csv, charts, crops and report.html to " << o.run.out << "\n";
  return 0;
}

}  // namespace ecoview
