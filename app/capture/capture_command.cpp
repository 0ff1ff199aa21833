#include "app/capture/capture_command.hpp"

#include "app/bench/shadow_figures.hpp"
#include "app/capture/aliasing_colours.hpp"
#include "app/capture/aov.hpp"
#include "app/capture/frame_video.hpp"
#include "app/capture/png.hpp"
#include "app/cli/options.hpp"
#include "app/cli/progress.hpp"
#include "app/cli/scene_info.hpp"
#include "app/errors.hpp"
#include "app/file_io.hpp"
#include "app/gl/context.hpp"
#include "app/render/renderer.hpp"
#include "app/scene/camera_path.hpp"
#include "shadow/aliasing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

namespace ecoview {
namespace {

namespace fs = std::filesystem;

FrameRange default_frames(const std::optional<CameraPath>& path, double fps) {
  if (!path) return {0, 1};
  const double frames = std::floor(path->duration() * fps + 1e-9) + 1.0;  // every t in [0, duration]
  if (frames > max_frame_count) {
    throw InputError("--fps: the path at this rate has " + std::to_string(static_cast<long long>(frames)) +
                     " frames, more than " + std::to_string(max_frame_count) + "; lower --fps or give --frames");
  }
  return {0, static_cast<int>(frames)};
}

// Whether a frame's file is there whole (files are renamed into place once written); anything but
// a file in its place is bad input.
bool finished(const fs::path& file) {
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (!fs::exists(status)) return false;
  if (!fs::is_regular_file(status)) throw InputError("--out: " + file.string() + " exists and is not a file");
  return fs::file_size(file, ec) > 0 && !ec;
}

// The names of the files these frames write in `out`.
std::set<std::string> frame_files(const fs::path& out, const std::vector<Aov>& aovs, AovFormat format,
                                  const std::vector<int>& frames) {
  std::set<std::string> names;
  for (int frame : frames) {
    for (Aov aov : aovs) names.insert(aov_file(out, aov, frame, format).filename().string());
  }
  return names;
}

// GPU milliseconds by stage.
nlohmann::json stage_figures(const FrameStats& s) {
  nlohmann::json stages = nlohmann::json::object();
  for (const auto& [stage, ms] : s.stage_ms) stages[stage] = ms;
  return stages;
}

// A paged map's pages (FrameStats::Pages); null for other methods.
nlohmann::json page_figures(const RenderOptions& options, const FrameStats& s) {
  const shadow::Technique* t = shadow::find_technique(options.method);
  if (!t || t->lookup != shadow::Lookup::pages) return nullptr;
  return {{"requested", s.pages.requested}, {"drawn", s.pages.drawn}, {"cached", s.pages.cached}, {"dropped", s.pages.dropped},
          {"tiles", s.pages.tiles}};
}

// A landscape's pool this frame (FrameStats::landscape); null in a scene without one.
nlohmann::json landscape_figures(const Renderer& renderer) {
  if (!renderer.has_landscapes()) return nullptr;
  const pointgen::LandscapePool::Stats& l = renderer.stats().landscape;
  return {{"cells", l.cells}, {"plants", l.plants}, {"cells_made", l.cells_made}, {"plants_made", l.plants_made},
          {"cells_left_out", l.cells_left_out}, {"plants_kept", l.plants_kept}, {"blocks", l.blocks}, {"far_plants", l.far_plants}, {"far_share", l.far_share}};
}

// One frame's figures for --stats (names as docs/figures.md defines them).
// render_ms: the wall time of this one frame, sampling, passes and read-backs, until glFinish.
nlohmann::json frame_stats(int frame, double t, double render_ms, const RenderOptions& options, const Renderer& renderer) {
  const FrameStats& s = renderer.stats();
  return {{"frame", frame}, {"t", t}, {"method", options.method}, {"shadow_size", options.shadow_size},
          {"shadow_setup", options.method == "none" ? "none" : renderer.shadow_setup().description}, {"render_ms", render_ms},
          {"alias_p95", alias_percentile(renderer.frame().read_aliasing(), renderer.frame().read_visibility(), shadow::p95_fraction)},
          {"sample_ms", s.sample_ms}, {"host_ms", s.host_ms}, {"shadow_pass_ms", s.shadow_pass_ms}, {"frame_pass_ms", s.frame_pass_ms},
          {"points", s.points}, {"triangles", s.triangles}, {"shadow_points", s.shadow_points},
          {"shadow_triangles", s.shadow_triangles}, {"points_left_out", s.points_left_out}, {"stage_ms", stage_figures(s)},
          {"pages", page_figures(options, s)}, {"landscape", landscape_figures(renderer)}};
}

}  // namespace

CLI::App* add_capture_command(CLI::App& app, CaptureOptions& o) {
  CLI::App* cmd = app.add_subcommand("capture", "Render frames headless to DIR/<aov>_<frame>.png or .exr (and an MP4)");
  add_scene_options(*cmd, o.scene);
  cmd->add_option("--path", o.path, "Camera path JSON file or shipped path (default: the scene's camera)");
  add_render_options(*cmd, o.render);
  cmd->add_option("--backend", o.backend, "GL context: egl (GPU device or Mesa surfaceless) or osmesa")
      ->capture_default_str();
  cmd->add_option("--frames", o.frames, "A:B renders frames A to B-1 (default: all the path at --fps, or 0)");
  cmd->add_option("--fps", o.fps, "Frames per second: frame i is at time i / fps")->capture_default_str();
  cmd->add_option("--aov", o.aov, "Images a frame: color,shadow,depth,aliasing,shadowmap,reference; none")
      ->capture_default_str();
  cmd->add_option("--aov-format", o.aov_format, "png, or exr: depth, shadow and reference as 32-bit float OpenEXR")
      ->capture_default_str();
  cmd->add_option("--video", o.video, "Also write the color frames as H.264 in this MP4 file, at --fps");
  cmd->add_flag("--force", o.force, "Render frames again where their files exist (default: resume)");
  cmd->add_option("--stats", o.stats, "Also write each frame's figures (alias_p95, times) to this JSON file");
  cmd->add_option("--out", o.out, "Output folder, created if missing (required)");
  return cmd;
}

int run_capture(const CaptureOptions& o) {
  // Check every input before any file is written.
  RenderSettings settings = render_settings(o.render);
  const double fps = check_fps(o.fps);
  const std::vector<Aov> aovs = parse_aov_list(o.aov);
  const AovFormat aov_format = parse_aov_format(o.aov_format);
  if (aovs.empty() && o.stats.empty()) throw InputError("--aov none writes no images: give --stats for the frames' figures");
  settings.aliasing = !o.stats.empty() || std::find(aovs.begin(), aovs.end(), Aov::aliasing) != aovs.end();
  if (std::find(aovs.begin(), aovs.end(), Aov::shadowmap) != aovs.end() &&
      !shadow::technique(settings.method).has_map()) {
    throw InputError("--aov: shadowmap needs a shadow map; --method " + o.render.method + " has none");
  }
  if (std::find(aovs.begin(), aovs.end(), Aov::shadowmap) != aovs.end() &&
      shadow::technique(settings.method).lookup == shadow::Lookup::pages) {
    throw InputError("--aov: shadowmap shows one map a view; --method " + o.render.method + " keeps pages of many levels");
  }
  check_backend(o.backend);
  const bool frames_asked = !o.frames.empty();
  const FrameRange asked_frames = frames_asked ? parse_frames(o.frames) : FrameRange{};
  check_out_folder(o.out);
  check_output_file("--stats", o.stats, o.out);
  const glm::ivec2 size(settings.width, settings.height);
  check_video_option(o.video, o.out, size, std::find(aovs.begin(), aovs.end(), Aov::color) != aovs.end());
  const auto load_start = std::chrono::steady_clock::now();
  const Scene scene = load_scene_option(o.scene);
  std::cout << describe_scene(scene, std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count())
            << std::endl;
  const shadow::Light& light = select_light(scene, o.scene.light);
  note_light_handed_over(settings.method, light, o.scene.light);
  std::optional<CameraPath> path;
  if (!o.path.empty()) path = CameraPath::load(open_input(o.path, "paths"));
  const FrameRange frames = frames_asked ? asked_frames : default_frames(path, fps);

  const fs::path out(o.out);
  std::vector<int> todo;
  for (int frame = frames.begin; frame < frames.end; ++frame) {
    bool done = !aovs.empty();
    for (Aov aov : aovs) done = finished(aov_file(out, aov, frame, aov_format)) && done;
    if (o.force || !done) todo.push_back(frame);
  }
  if (!o.video.empty()) check_skipped_frames(out, frames, todo, size);
  const auto write_video = [&] {
    if (o.video.empty()) return;
    remove_stale_temporaries(fs::absolute(o.video).parent_path(), {fs::path(o.video).filename().string()});
    write_frame_video(o.video, out, frames, size, fps);
    std::cout << "capture: wrote " << frames.end - frames.begin << " frame(s) as a video to " << o.video << "\n";
  };
  const int total = frames.end - frames.begin;
  if (todo.empty()) {
    std::cout << "capture: all " << total << " frames already in " << o.out << " (--force renders them again)\n";
    write_video();
    return 0;
  }

  const auto start = std::chrono::steady_clock::now();
  const std::unique_ptr<GlContext> context = create_headless_context(o.backend);
  Renderer renderer(scene, settings);
  make_out_folder(o.out);  // once the driver has taken the settings
  if (std::find(aovs.begin(), aovs.end(), Aov::aliasing) != aovs.end()) {
    write_file_atomically(out / "aliasing_legend.png", encode_png(aliasing_legend()));
  }
  // A process killed while writing a file left its temporary one; the files written again here
  // take theirs away.
  remove_stale_temporaries(out, frame_files(out, aovs, aov_format, todo));
  if (!o.stats.empty()) remove_stale_temporaries(fs::absolute(o.stats).parent_path(), {fs::path(o.stats).filename().string()});
  Progress progress("capture: frame", todo.size());
  nlohmann::json stats = nlohmann::json::array();
  const auto time_of = [&](int frame) { return static_cast<double>(frame) / fps; };
  const auto camera_at = [&](int frame) { return path ? path->at(time_of(frame), scene.camera) : scene.camera; };
  int last_rendered = -1;
  for (int frame : todo) {
    const double t = time_of(frame);
    const shadow::Camera camera = camera_at(frame);
    const auto render_start = std::chrono::steady_clock::now();
    // A frame takes things from the one before (Renderer::start_after): where this process did not
    // render that one, it is made, so the frame has the same bytes however a capture is split.
    if (frame > 0 && last_rendered != frame - 1) renderer.start_after(camera_at(frame - 1), light, time_of(frame - 1));
    renderer.render(camera, light, t);
    last_rendered = frame;
    glFinish();
    const double render_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - render_start).count();
    for (Aov aov : aovs) {
      write_file_atomically(aov_file(out, aov, frame, aov_format), encode_aov(aov, renderer, camera.far, aov_format));
    }
    if (!o.stats.empty()) stats.push_back(frame_stats(frame, t, render_ms, o.render, renderer));
    progress.step();
  }
  progress.finish();
  if (!o.stats.empty()) write_file_atomically(o.stats, stats.dump(2) + "\n");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "capture: wrote " << todo.size() << " frame(s) to " << o.out;
  std::cout << "; the last drew " << renderer.stats().points << " points and " << renderer.stats().triangles << " triangles";
  if (static_cast<int>(todo.size()) < total) std::cout << " (" << total - static_cast<int>(todo.size()) << " already there)";
  std::printf(" in %.1f s on %s\n", seconds, context->description().c_str());
  if (const std::size_t left_out = renderer.stats().points_left_out; left_out > 0) {
    std::cout << "capture: the last frame chose " << left_out << " points more than this driver's buffers hold; "
              << "they were not drawn (fewer plants, or a smaller --shadow-size or --k, draw them all)\n";
  }
  write_video();
  return 0;
}

}  // namespace ecoview
