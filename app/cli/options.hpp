#pragma once
#include "app/render/render_settings.hpp"
#include "app/scene/scene.hpp"
#include "app/scene/scene_file.hpp"

#include <CLI/CLI.hpp>

#include <glm/glm.hpp>

#include <string>
#include <utility>

// Validation of command-line values shared by the subcommands; each throws InputError naming
// the option.
namespace ecoview {

// The longest line the help gives an option, a command or a footer.
constexpr std::size_t max_help_line = 100;

glm::ivec2 parse_size(const std::string& text);  // "WxH"

struct FrameRange {
  int begin = 0;
  int end = 1;  // one past the last frame
};
// Frame numbers are written with 5 digits.
constexpr int max_frame_count = 100000;
FrameRange parse_frames(const std::string& text);  // "A:B", frames A … B-1, B at most max_frame_count

int check_shadow_size(int size);

// The scene options capture and view share: --scene, --light, --memory-budget, --plant-pool.
struct SceneOptions {
  std::string name;  // a file or a shipped scene; empty: the default scene
  int light = 0;
  double memory_budget_gib = 4.0;
  double plant_pool_mib = LoadLimits{}.plant_pool_bytes / (1024.0 * 1024.0);
};
void add_scene_options(CLI::App& command, SceneOptions& options);

// The rendering options capture and view share: --size, --shadow-size, --method, --geometry,
// --k, --splat, --bias-slope, --bias-constant, --shadow-depth.
struct RenderOptions {
  std::string size = "1280x720";
  int shadow_size = 2048;
  std::string method = "psm";  // the perspective shadow map, the project's core
  std::string geometry = "points";
  std::string sampler = "gpu";
  double k = RenderSettings{}.k;
  int splat = RenderSettings{}.splat_size;
  double bias_slope = RenderSettings{}.shadow_bias.slope;
  double bias_constant = RenderSettings{}.shadow_bias.constant;
  std::string shadow_depth = shadow_depth_name(RenderSettings{}.shadow_depth);
  int page_pool = RenderSettings{}.page_pool_mib;
};
void add_render_options(CLI::App& command, RenderOptions& options);
// Validated settings; throws InputError naming the option.
RenderSettings render_settings(const RenderOptions& options);
double check_fps(double fps);

// What `density` and `bench` share: --size, --backend, --memory-budget, --quick, --out.
struct BenchmarkOptions {
  explicit BenchmarkOptions(std::string default_size) : size(std::move(default_size)) {}
  std::string size;
  std::string backend = "egl";
  bool quick = false;  // a few short runs, to check the pipeline (tests)
  double memory_budget_gib = 4.0;
  std::string out;
};
void add_benchmark_options(CLI::App& command, BenchmarkOptions& options, const std::string& quick_help);
// The settings a benchmark starts from: the defaults at its --size.
RenderSettings benchmark_settings(const BenchmarkOptions& options);

// Checks a --backend name (egl or osmesa) before any work is done.
const std::string& check_backend(const std::string& backend);

// Checks a file option (`--stats FILE`) before any work: not a folder (nor `out_folder` itself), and
// in a folder where a file can be made, or in `out_folder`, the --out folder the command will make.
// An empty file passes.
void check_output_file(const std::string& option, const std::string& file, const std::string& out_folder = "");

// Checks the --out folder before any work: named, and a folder or a path one can be made at (the
// nearest part of it that exists is a folder one can write in).
void check_out_folder(const std::string& out);

// Checks the --out folder and makes it; RuntimeFailure when it cannot be made.
void make_out_folder(const std::string& out);

// The scene named by --scene (a file or a shipped scene; the default scene when empty), refused
// when it would need more than `memory_budget_gib` (--memory-budget); its landscapes' plants take
// at most `plant_pool_mib` (--plant-pool).
Scene load_scene_option(const std::string& scene, double memory_budget_gib, double plant_pool_mib = SceneOptions{}.plant_pool_mib);
Scene load_scene_option(const SceneOptions& options);
// The light selected by --light.
const shadow::Light& select_light(const Scene& scene, int index);
// Says in a note on stderr where --method hands the light (number `index`) to the uniform map
// (shadow::Technique::warps): the frames then show that map's shadows, not the method's.
void note_light_handed_over(shadow::Method method, const shadow::Light& light, int index);

}  // namespace ecoview
