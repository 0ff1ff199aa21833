#include "app/cli/options.hpp"

#include "app/errors.hpp"
#include "app/file_io.hpp"
#include "app/scene/scene_file.hpp"
#include "shadow/techniques.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <regex>
#include <sstream>
#include <utility>
#include <vector>

namespace ecoview {

glm::ivec2 parse_size(const std::string& text) {
  std::smatch m;
  if (!std::regex_match(text, m, std::regex(R"((\d{1,6})x(\d{1,6}))"))) {
    throw InputError("--size: expected WIDTHxHEIGHT such as 1280x720, got '" + text + "'");
  }
  const glm::ivec2 size(std::stoi(m[1]), std::stoi(m[2]));
  if (size.x < 1 || size.y < 1 || size.x > 16384 || size.y > 16384) {
    throw InputError("--size: width and height must be between 1 and 16384, got '" + text + "'");
  }
  return size;
}

FrameRange parse_frames(const std::string& text) {
  std::smatch m;
  if (!std::regex_match(text, m, std::regex(R"((\d{1,9}):(\d{1,9}))"))) {
    throw InputError("--frames: expected A:B (frames A to B-1) such as 0:30, got '" + text + "'");
  }
  const FrameRange range{std::stoi(m[1]), std::stoi(m[2])};
  if (range.end <= range.begin) {
    throw InputError("--frames: B must be greater than A (frames A to B-1), got '" + text + "'");
  }
  if (range.end > max_frame_count) {
    throw InputError("--frames: frames are numbered below " + std::to_string(max_frame_count) + " (5 digits), got '" + text + "'");
  }
  return range;
}

int check_shadow_size(int size) {
  if (size < 16 || size > 16384) {
    throw InputError("--shadow-size: must be between 16 and 16384, got " + std::to_string(size));
  }
  return size;
}

void add_scene_options(CLI::App& command, SceneOptions& o) {
  command.add_option("--scene", o.name, "Scene JSON file or shipped scene (ecoview scenes lists them)");
  command.add_option("--light", o.light, "Index of the scene light that shines and casts shadows")->capture_default_str();
  command.add_option("--memory-budget", o.memory_budget_gib, "Refuse scenes that would need more memory than this, in GiB")
      ->capture_default_str();
  command.add_option("--plant-pool", o.plant_pool_mib, "MiB for a landscape's plants near the camera, made as it moves")
      ->capture_default_str();
}

namespace {

// The words of `text` in lines of at most `width` characters, the lines after the first indented
// by two spaces.
std::string wrapped(const std::string& text, std::size_t width) {
  std::string lines, line;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    if (line.empty()) {
      line = word;
    } else if (line.size() + 1 + word.size() <= width) {
      line += " " + word;
    } else {
      lines += line + "\n";
      line = "  " + word;
    }
  }
  return lines + line;
}

const char* light_type_name(shadow::LightType type) {
  return type == shadow::LightType::directional ? "directional" : type == shadow::LightType::point ? "point" : "spot";
}

// The lights in `lights`: "point and spot".
std::string light_names(const shadow::Lights& lights) {
  std::string names;
  for (const shadow::LightType type : {shadow::LightType::directional, shadow::LightType::point, shadow::LightType::spot}) {
    if (lights.has(type)) names += (names.empty() ? "" : " and ") + std::string(light_type_name(type));
  }
  return names;
}

// A line on stderr beside the output, as the scene file's notes (Scene::notes) are written.
void note(const std::string& line) { std::cerr << "ecoview: note: " << line << "\n"; }

// The methods whose own setup handles exactly `lights`: "dpsm and ipsm".
std::string methods_for(const shadow::Lights& lights) {
  std::string names;
  for (const shadow::Technique& t : shadow::techniques()) {
    if (t.warps == lights) names += (names.empty() ? "" : " and ") + t.name;
  }
  return names;
}

// The methods --method takes, a line each with what it is, and those that hand some lights to the
// uniform map, from the table: the help's footer, as the option's own line has no room for them.
std::string methods_footer() {
  std::string lines = "Shadow methods (--method):";
  std::string handed_over;
  std::vector<shadow::Lights> seen;
  for (const shadow::Technique& t : shadow::techniques()) {
    lines += "\n  " + t.name + ": " + t.help;
    if (t.warps.all() || std::find(seen.begin(), seen.end(), t.warps) != seen.end()) continue;
    seen.push_back(t.warps);
    handed_over += methods_for(t.warps) + " take only " + light_names(t.warps) + " lights; ";
  }
  return lines + "\n" + wrapped(handed_over + "they hand other lights to the uniform map.", max_help_line);
}

shadow::Method parse_method(const std::string& name) {
  if (const shadow::Technique* t = shadow::find_technique(name)) return t->method;
  std::string names;
  for (const shadow::Technique& t : shadow::techniques()) names += (names.empty() ? "" : ", ") + t.name;
  throw InputError("--method: '" + name + "' is not available in this build (available: " + names + ")");
}

float check_bias(const char* option, double bias) {
  if (!std::isfinite(bias) || bias < 0.0 || bias > 1e6) throw InputError(std::string(option) + ": must be between 0 and 1000000");
  return static_cast<float>(bias);
}

ShadowDepth parse_shadow_depth(const std::string& name) {
  for (ShadowDepth depth : shadow_depths) {
    if (shadow_depth_name(depth) == name) return depth;
  }
  throw InputError("--shadow-depth: expected 16, 24 or 32f, got '" + name + "'");
}

}  // namespace

void add_render_options(CLI::App& command, RenderOptions& o) {
  command.add_option("--size", o.size, "Frame size WIDTHxHEIGHT")->capture_default_str();
  command.add_option("--shadow-size", o.shadow_size, "Shadow map texels a side (adaptive's virtual maps keep their size)")
      ->capture_default_str();
  command.add_option("--method", o.method, "Shadow method, one of those listed below")->capture_default_str();
  command.add_option("--geometry", o.geometry, "points (far plants, people, animals as point splats) or polygons")
      ->capture_default_str();
  command.add_option("--sampler", o.sampler, "Where the frame's points and polygons are chosen: gpu or cpu")
      ->capture_default_str();
  command.add_option("--k", o.k, "Point density: points per pixel of projected surface")->capture_default_str();
  command.add_option("--splat", o.splat, "Splat size in pixels (per side)")->capture_default_str();
  command.add_option("--bias-slope", o.bias_slope, "Depth bias that grows with the depth slope (glPolygonOffset factor)")
      ->capture_default_str();
  command.add_option("--bias-constant", o.bias_constant, "Constant depth bias, in depth steps (glPolygonOffset units)")
      ->capture_default_str();
  command.add_option("--shadow-depth", o.shadow_depth, "Shadow maps' depth format: 16, 24 (fixed point) or 32f (float)")
      ->capture_default_str();
  command.add_option("--page-pool", o.page_pool, "adaptive methods: MiB for the pages they keep drawn")->capture_default_str();
  command.footer(methods_footer());
}

RenderSettings render_settings(const RenderOptions& o) {
  const glm::ivec2 size = parse_size(o.size);
  RenderSettings settings;
  settings.width = size.x;
  settings.height = size.y;
  settings.shadow_size = check_shadow_size(o.shadow_size);
  settings.method = parse_method(o.method);
  if (o.geometry != "points" && o.geometry != "polygons") {
    throw InputError("--geometry: expected points or polygons, got '" + o.geometry + "'");
  }
  settings.points = o.geometry == "points";
  if (o.sampler != "cpu" && o.sampler != "gpu") throw InputError("--sampler: expected cpu or gpu, got '" + o.sampler + "'");
  settings.gpu_sampler = o.sampler == "gpu";
  if (!std::isfinite(o.k) || o.k <= 0.0 || o.k > 1000.0) throw InputError("--k: must be above 0 and at most 1000");
  settings.k = static_cast<float>(o.k);
  if (o.splat < 1 || o.splat > 16) throw InputError("--splat: must be between 1 and 16 pixels");
  settings.splat_size = o.splat;
  settings.shadow_bias = {check_bias("--bias-slope", o.bias_slope), check_bias("--bias-constant", o.bias_constant)};
  settings.shadow_depth = parse_shadow_depth(o.shadow_depth);
  if (o.page_pool < 1 || o.page_pool > 65536) throw InputError("--page-pool: must be between 1 and 65536 MiB");
  settings.page_pool_mib = o.page_pool;
  return settings;
}

double check_fps(double fps) {
  if (!std::isfinite(fps) || fps <= 0.0 || fps > 10000.0) {
    throw InputError("--fps: must be a number above 0 and at most 10000");
  }
  return fps;
}

const std::string& check_backend(const std::string& backend) {
  if (backend != "egl" && backend != "osmesa") {
    throw InputError("--backend: unknown backend '" + backend + "' (available: egl, osmesa)");
  }
  return backend;
}

RenderSettings benchmark_settings(const BenchmarkOptions& options) {
  const glm::ivec2 size = parse_size(options.size);
  RenderSettings settings;
  settings.width = size.x;
  settings.height = size.y;
  return settings;
}

// `path` made absolute, without ".", ".." or a trailing separator.
static std::filesystem::path normal_folder(const std::string& path) {
  return (std::filesystem::absolute(path) / "x").lexically_normal().parent_path();
}

void check_output_file(const std::string& option, const std::string& file, const std::string& out_folder) {
  namespace fs = std::filesystem;
  if (file.empty()) return;
  const fs::path name = fs::path(file).filename();
  std::error_code ec;
  if (name.empty() || name == "." || name == ".." || fs::is_directory(file, ec)) {
    throw InputError(option + ": " + file + " is a folder, not a file");
  }
  if (!out_folder.empty() && normal_folder(file) == normal_folder(out_folder)) {
    throw InputError(option + ": " + file + " is the --out folder; name a file (in it or elsewhere)");
  }
  if (const auto reason = refused_file_name(file)) throw InputError(option + ": " + file + ": " + *reason);
  const fs::path folder = fs::absolute(file).lexically_normal().parent_path();
  if (fs::is_directory(folder, ec)) {
    if (const auto reason = cannot_write_in(folder)) throw InputError(option + ": " + file + ": cannot be written there (" + *reason + ")");
    return;
  }
  if (!out_folder.empty() && folder == normal_folder(out_folder)) return;
  throw InputError(option + ": " + file + ": its folder does not exist");
}

void check_out_folder(const std::string& out) {
  namespace fs = std::filesystem;
  if (out.empty()) throw InputError("--out is required: the folder to write into");
  std::error_code ec;
  for (fs::path p = normal_folder(out); !p.empty(); p = p.parent_path()) {
    if (fs::exists(p, ec)) {
      if (!fs::is_directory(p, ec)) throw InputError("--out: " + out + ": " + p.string() + " is a file, not a folder");
      if (const auto reason = cannot_write_in(p)) throw InputError("--out: " + out + ": cannot write in " + p.string() + " (" + *reason + ")");
      break;
    }
    if (p == p.parent_path()) break;
  }
  if (const auto reason = refused_name(out)) throw InputError("--out: " + out + ": " + *reason);
}

void make_out_folder(const std::string& out) {
  namespace fs = std::filesystem;
  check_out_folder(out);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec || !fs::is_directory(out)) {
    throw RuntimeFailure("--out: cannot create folder " + out + " (" + ec.message() + "); check permissions and free space");
  }
}

Scene load_scene_option(const SceneOptions& options) {
  return load_scene_option(options.name, options.memory_budget_gib, options.plant_pool_mib);
}

Scene load_scene_option(const std::string& scene, double memory_budget_gib, double plant_pool_mib) {
  if (!std::isfinite(memory_budget_gib) || memory_budget_gib <= 0.0) {
    throw InputError("--memory-budget: must be a positive number of GiB");
  }
  if (!std::isfinite(plant_pool_mib) || plant_pool_mib < 1.0 || plant_pool_mib > 1024.0 * 1024.0) {
    throw InputError("--plant-pool: must be between 1 and 1048576 MiB");
  }
  Scene loaded = load_scene(open_input(scene.empty() ? default_scene_name : scene, "scenes"),
                             {memory_budget_gib * 1024.0 * 1024.0 * 1024.0, plant_pool_mib * 1024.0 * 1024.0});
  for (const std::string& line : loaded.notes) note(line);
  return loaded;
}

const shadow::Light& select_light(const Scene& scene, int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= scene.lights.size()) {
    throw InputError("--light: " + scene.name + " has " + std::to_string(scene.lights.size()) +
                     " light(s), numbered from 0; got " + std::to_string(index));
  }
  return scene.lights[static_cast<std::size_t>(index)];
}

void note_light_handed_over(shadow::Method method, const shadow::Light& light, int index) {
  const shadow::Technique& t = shadow::technique(method);
  if (t.warps.has(light.type)) return;
  note("--method " + t.name + " takes only " + light_names(t.warps) + " lights; light " + std::to_string(index) + " is a " +
       light_type_name(light.type) + " light, so its shadows are the uniform map's");
}

void add_benchmark_options(CLI::App& command, BenchmarkOptions& o, const std::string& quick_help) {
  command.add_option("--size", o.size, "Frame size WIDTHxHEIGHT")->capture_default_str();
  command.add_option("--backend", o.backend, "GL context: egl or osmesa")->capture_default_str();
  command.add_option("--memory-budget", o.memory_budget_gib, "Refuse scenes needing more memory than this, in GiB")
      ->capture_default_str();
  command.add_flag("--quick", o.quick, quick_help);
  command.add_option("--out", o.out, "Output folder, created if missing (required)");
}

}  // namespace ecoview
