#include "app/bench/paper_suite.hpp"

#include "app/bench/charts.hpp"
#include "app/bench/measured_view.hpp"
#include "app/capture/aov.hpp"
#include "app/capture/png.hpp"
#include "app/cli/progress.hpp"
#include "app/file_io.hpp"
#include "app/gl/context.hpp"
#include "app/scene/camera_path.hpp"
#include "app/scene/scene_file.hpp"

#include <array>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace ecoview {
namespace {

namespace fs = std::filesystem;

// What each figure shows, as the paper says it: the report's captions.
const std::vector<std::pair<std::string, std::string>> claims = {
    {"fig1", "Stamminger and Drettakis 2002, Fig. 1: a uniform 512² map against a perspective one of the same size; the "
             "PSM's shadows are sharp near the viewer, and its map (right) spends its texels there."},
    {"fig8", "Fig. 8: the cathedral square, uniform (left half) against PSM (right half) at 1024²; the PSM costs "
             "about the same time."},
    {"fig9", "Fig. 9: the street with moving cars and planes, PSM at 1024², interactive along the path."},
    {"fig10", "Fig. 10: the ecosystem of point-rendered plants, no shadows against uniform and PSM maps at 1024²: "
              "the shadow pass costs about as much as the frame, the PSM about as much as the uniform map."},
    {"ipsm", "Vanek et al. 2011, Table 1: uniform, dual paraboloid and improved paraboloid maps for point and spot "
             "lights at 512² and 2048²: the IPSM is as fast as the DPSM and errs less."},
    {"overhead", "PSM implementation note (2002), Fig. 1: a light perpendicular to the view (there approximated by a "
                 "light high overhead) at 128²: the PSM's best case, its shadows near the viewer sharper than the "
                 "uniform map's."},
    {"bias", "The same note, Fig. 5: with the light behind the viewer (inverted in post-perspective space) the bias "
             "is hard to choose: too little leaves acne, too much loses shadows (leak). The constant bias swept in "
             "each depth format, the slope in 32-bit float."},
    {"depth", "Kilgard 2001: depth maps hold 16 or 24 bits; more precision needs less bias, and too few bits break "
              "down over a large light frustum. The field's lights turned 0-180° from the view, uniform and PSM "
              "maps at 1024² in each format, default bias."},
};

constexpr std::size_t across_the_view = 6;  // the field's light at 90° to the view
// The bias sweep: constants with the default slope, then slopes with the default constant.
constexpr std::array<float, 6> bias_constants = {0.0f, 4.0f, 1e3f, 1e5f, 1e6f, 1e7f};
constexpr std::array<float, 4> bias_slopes = {0.0f, 8.0f, 64.0f, 512.0f};
constexpr int street_frames = 6, quick_street_frames = 2;
// The depth formats' light sweep: every field light, or 0°, 90° and 180° only.
constexpr std::size_t light_step = 1, quick_light_step = 6;
constexpr std::array<shadow::Method, 2> depth_methods = {shadow::Method::uniform, shadow::Method::psm};

struct Timing {
  int warmup, frames;
};

class PaperSuite {
 public:
  explicit PaperSuite(const BenchmarkOptions& o)
      : o_(o), out_(o.out), base_(benchmark_settings(o)), quick_(o.quick), field_(load("field")) {
    fs::create_directories(out_ / "images");
  }

  // Fig. 1: the chess board under its spot light, uniform against PSM at 512², with their maps.
  void fig1(Progress& progress) {
    const Loaded chess = load("chess");
    for (shadow::Method m : {shadow::Method::uniform, shadow::Method::psm}) {
      Renderer renderer(chess.scene, settings(chess, m, 512));
      add("fig1", "chess", renderer, chess.view(chess.scene.lights[0]), small_timing());
      write_png("paper_fig1_" + shadow::technique(m).name + "_map.png", encode_aov(Aov::shadowmap, renderer, chess.scene.camera.far));
      progress.step();
    }
  }

  // Fig. 8: the square, its left half with the uniform map and its right half with the PSM at 1024².
  void fig8(Progress& progress) {
    const Loaded square = load("square");
    Image8 halves;
    for (shadow::Method m : {shadow::Method::uniform, shadow::Method::psm}) {
      Renderer renderer(square.scene, settings(square, m, 1024));
      add("fig8", "square", renderer, square.view(square.scene.lights[0]), small_timing());
      const Image8 color = renderer.frame().read_color();
      if (m == shadow::Method::uniform) {
        halves = color;
      } else {
        for (int y = 0; y < color.height; ++y) {
          for (int x = color.width / 2; x < color.width; ++x) {
            for (int c = 0; c < 3; ++c) halves.samples[(static_cast<std::size_t>(y) * color.width + x) * 3 + c] = color.at(x, y, c);
          }
        }
      }
      progress.step();
    }
    write_png("paper_fig8_halves.png", encode_png(halves));
  }

  // Fig. 9: the street along its path, PSM at 1024², frames spread over it.
  void fig9(Progress& progress) {
    const Loaded street = load("street");
    const CameraPath path = CameraPath::load(open_input("street", "paths"));
    Renderer renderer(street.scene, settings(street, shadow::Method::psm, 1024));
    const int frames = quick_ ? quick_street_frames : street_frames;
    for (int f = 0; f < frames; ++f) {
      const double t = path.duration() * f / (frames - 1);
      MeasuredView view = street.view(street.scene.lights[0]);
      view.camera = path.at(t, street.scene.camera);
      view.t = t;
      BenchRun& run = add("fig9", "street", renderer, view, small_timing(), f == frames / 2);
      run.params.update({{"frame", f}, {"t", t}});
      progress.step();
    }
  }

  // Fig. 10: the ecosystem without shadows, with the uniform map and with the PSM at 1024².
  void fig10(Progress& progress) {
    const std::string name = quick_ ? "courtyard" : default_scene_name;
    const Loaded eco = load(name);
    for (shadow::Method m : {shadow::Method::none, shadow::Method::uniform, shadow::Method::psm}) {
      Renderer renderer(eco.scene, settings(eco, m, 1024));
      add("fig10", name, renderer, eco.view(eco.scene.lights[0]), quick_ ? small_timing() : Timing{1, 3});
      progress.step();
    }
  }

  // Vanek et al.'s Table 1: uniform, DPSM and IPSM at 512² and 2048² under a point light (the
  // courtyard's) and a spot light (the chess board's).
  void ipsm_table(Progress& progress) {
    for (const auto& [name, light] : {std::pair<const char*, int>{"courtyard", 2}, std::pair<const char*, int>{"chess", 0}}) {
      const Loaded scene = load(name);
      for (int size : {512, 2048}) {
        for (shadow::Method m : {shadow::Method::uniform, shadow::Method::dpsm, shadow::Method::ipsm}) {
          Renderer renderer(scene.scene, settings(scene, m, size));
          add("ipsm", name, renderer, scene.view(scene.scene.lights[static_cast<std::size_t>(light)]), small_timing(), size == 512);
          progress.step();
        }
      }
    }
  }

  // The implementation note's light perpendicular to the view at 128² (which it approximates by
  // a light high overhead; on the field, its light 6, across the view), uniform against PSM; and
  // its bias sweep with the light behind the viewer (the field's light 0, along the view: inverted
  // for the PSM), constant bias with the default slope and slope with the default constant.
  void implementation_note(Progress& progress) {
    const Loaded& field = field_;
    for (shadow::Method m : {shadow::Method::uniform, shadow::Method::psm}) {
      Renderer renderer(field.scene, settings(field, m, 128));
      add("overhead", "field", renderer, field.view(field.scene.lights[across_the_view]), small_timing());
      progress.step();
    }
    const DepthBias defaults;
    for (ShadowDepth depth : shadow_depths) {
      for (float constant : bias_constants) bias_run(field, {defaults.slope, constant}, depth, progress);
    }
    for (float slope : bias_slopes) bias_run(field, {slope, defaults.constant}, ShadowDepth::float32, progress);
  }

  // Kilgard's precision: acne and leak in each depth format as the field's light turns from behind
  // the viewer (inverted for the PSM) to facing it.
  void depth_formats(Progress& progress) {
    const Loaded& field = field_;
    for (ShadowDepth depth : shadow_depths) {
      for (std::size_t l = 0; l < field.scene.lights.size(); l += quick_ ? quick_light_step : light_step) {
        for (shadow::Method m : depth_methods) {
          RenderSettings s = settings(field, m, 1024);
          s.shadow_depth = depth;
          Renderer renderer(field.scene, s);
          BenchRun& run = add("depth", "field", renderer, field.view(field.scene.lights[l]), small_timing(), false);
          run.params.update({{"shadow_depth", shadow_depth_name(depth)}, {"light_view_deg", field_light_step_deg * static_cast<float>(l)}});
          progress.step();
        }
      }
    }
  }

  // Fig. 1, 8: two methods; Fig. 9: its frames; Fig. 10: three methods; the table: two scenes, two
  // sizes, three methods; the overhead light: two methods; the bias sweep; the depth formats.
  std::size_t steps() const {
    const std::size_t step = quick_ ? quick_light_step : light_step;
    return 2 + 2 + static_cast<std::size_t>(quick_ ? quick_street_frames : street_frames) + 3 + 12 + 2 +
           shadow_depths.size() * bias_constants.size() + bias_slopes.size() +
           shadow_depths.size() * ((field_.scene.lights.size() + step - 1) / step) * depth_methods.size();
  }

  void finish(const std::string& renderer_name) {
    results_.machine = machine_info(renderer_name, o_.backend);
    results_.quick = quick_;
    write_results(out_, results_);
    draw_charts(out_, "paper_charts.py");
    write_report(out_, "ecoview bench --suite paper", "", report_body(), results_);
  }

 private:
  struct Loaded {
    Scene scene;
    std::unique_ptr<ExactVisibility> exact;
    MeasuredView view(const shadow::Light& light) const { return {scene, *exact, scene.camera, light, 0.0}; }
  };

  Loaded load(const std::string& name) const {
    Loaded loaded{load_scene_option(name, o_.memory_budget_gib), nullptr};
    loaded.exact = std::make_unique<ExactVisibility>(loaded.scene.meshes, loaded.scene.groups);
    return loaded;
  }

  // As bench sets them (for_scene: points off where the scene has no point meshes).
  RenderSettings settings(const Loaded& loaded, shadow::Method method, int shadow_size) const {
    RenderSettings s = base_;
    s.method = method;
    s.shadow_size = shadow_size;
    return for_scene(s, loaded.scene);
  }

  Timing small_timing() const { return quick_ ? Timing{0, 1} : Timing{2, 8}; }

  // Times and measures the renderer's frame of the view, and keeps its colour image.
  BenchRun& add(const std::string& figure, const std::string& scene, Renderer& renderer, const MeasuredView& view,
                Timing timing, bool image = true) {
    BenchRun run = measure_view(renderer, view, time_frames(renderer, view.camera, view.light, view.t, timing.warmup, timing.frames));
    const std::string method = shadow::technique(renderer.settings().method).name;
    run.params.update({{"sweep", "paper"}, {"figure", figure}, {"scene", scene}, {"method", method},
                       {"shadow_size", renderer.settings().method == shadow::Method::none ? 0 : renderer.settings().shadow_size}});
    if (image) {
      const std::string file = "paper_" + figure + "_" + scene + "_" + method + "_" + std::to_string(renderer.settings().shadow_size) + ".png";
      write_png(file, encode_png(renderer.frame().read_color()));
      images_[figure].push_back(file);
    }
    results_.runs.push_back(std::move(run));
    return results_.runs.back();
  }

  void bias_run(const Loaded& field, DepthBias bias, ShadowDepth depth, Progress& progress) {
    RenderSettings s = settings(field, shadow::Method::psm, 1024);
    s.shadow_bias = bias;
    s.shadow_depth = depth;
    Renderer renderer(field.scene, s);
    BenchRun& run = add("bias", "field", renderer, field.view(field.scene.lights[0]), small_timing(), false);
    run.params.update({{"bias_slope", bias.slope}, {"bias_constant", bias.constant}, {"shadow_depth", shadow_depth_name(depth)}});
    progress.step();
  }

  void write_png(const std::string& file, const std::string& png) const { write_file_atomically(out_ / "images" / file, png); }

  std::string report_body() const {
    std::ostringstream html;
    for (const auto& [figure, claim] : claims) {
      html << "<h2>" << figure << "</h2><p>" << claim << "</p><table><tr><th>scene</th><th>method</th><th>map</th>"
           << "<th>frame_ms</th><th>err</th><th>acne</th><th>leak</th><th>triangles</th><th>points</th><th>more</th></tr>\n";
      for (const BenchRun& run : results_.runs) {
        if (run.params["figure"] != figure) continue;
        html << "<tr><td>" << run.params["scene"].get<std::string>() << "</td><td>" << run.params["method"].get<std::string>()
             << "</td><td>" << run.params["shadow_size"] << "</td><td>" << static_cast<int>(run.figures["frame_ms"].get<double>())
             << "</td><td>" << 100.0 * run.figures["err"].get<double>() << " %</td><td>" << 100.0 * run.figures["acne"].get<double>()
             << " %</td><td>" << 100.0 * run.figures["leak"].get<double>() << " %</td><td>" << run.figures["triangles"]
             << "</td><td>" << run.figures["points"] << "</td><td>";
        for (const char* key : {"t", "bias_slope", "bias_constant", "shadow_depth", "light_view_deg"}) {
          if (run.params.contains(key)) html << key << " = " << run.params[key] << " ";
        }
        html << "</td></tr>\n";
      }
      html << "</table>\n";
      if (const auto images = images_.find(figure); images != images_.end()) {
        for (const std::string& file : images->second) html << "<img src=\"images/" << file << "\" title=\"" << file << "\">";
      }
      if (figure == "fig1") html << "<img src=\"images/paper_fig1_uniform_map.png\"><img src=\"images/paper_fig1_psm_map.png\">";
      if (figure == "fig8") html << "<img src=\"images/paper_fig8_halves.png\">";
      if (figure == "bias") html << "<img src=\"chart_bias.png\">";
      if (figure == "depth") html << "<img src=\"chart_depth.png\">";
      html << "\n";
    }
    return html.str();
  }

  const BenchmarkOptions& o_;
  fs::path out_;
  RenderSettings base_;
  bool quick_;
  BenchResults results_;
  std::map<std::string, std::vector<std::string>> images_;
  Loaded field_;  // the implementation note's and the depth formats' scene, loaded once
};

}  // namespace

void run_paper_suite(const BenchmarkOptions& o) {
  make_out_folder(o.out);
  const std::unique_ptr<GlContext> context = create_headless_context(o.backend);
  PaperSuite suite(o);
  Progress progress("bench --suite paper: run", suite.steps());
  suite.fig1(progress);
  suite.fig8(progress);
  suite.fig9(progress);
  suite.fig10(progress);
  suite.ipsm_table(progress);
  suite.implementation_note(progress);
  suite.depth_formats(progress);
  progress.finish();
  suite.finish(context->description());
  std::cout << "bench --suite paper: wrote results.json, results.csv, images and report.html to " << o.out << "\n";
}

}  // namespace ecoview
