#include "app/view/view_command.hpp"

#include "app/cli/scene_info.hpp"
#include "app/clock.hpp"
#include "app/errors.hpp"
#include "app/file_io.hpp"
#include "app/gl/glfw_window.hpp"
#include "app/view/viewer.hpp"

#include <filesystem>
#include <iostream>

namespace ecoview {

CLI::App* add_view_command(CLI::App& app, ViewOptions& o) {
  CLI::App* cmd = app.add_subcommand("view", "Fly through a scene in a window (WASD fly, Tab full HUD, Esc quits)");
  add_scene_options(*cmd, o.scene);
  add_render_options(*cmd, o.render);
  cmd->add_option("--play", o.play, "Camera path (file or shipped name) to follow from t = 0");
  cmd->add_option("--record", o.record, "File R writes the recorded camera path to (as --path reads it)")
      ->capture_default_str();
  cmd->add_option("--fps", o.fps, "Step time by 1/fps a frame, as capture does, not by the clock");
  cmd->add_option("--exit-after", o.exit_after, "Close after this many frames (0: when the window is closed)");
  cmd->add_option("--screenshot", o.screenshot, "Write the window (HUD included) at the last frame to this PNG");
  cmd->add_option("--out", o.out, "Folder P writes frames to, named as capture names them")->capture_default_str();
  cmd->add_flag("--no-hud", o.no_hud, "Start with the HUD hidden (H shows it)");
  cmd->add_flag("--full-hud", o.full_hud, "Start with the HUD's full panel unfolded (Tab folds it)");
  cmd->add_flag("--shadow-map-inset", o.shadow_map_inset, "Start with the HUD's inset of the shadow map on");
  cmd->add_flag("--aliasing-overlay", o.aliasing_overlay, "Start with the aliasing heat map (the aliasing AOV) on");
  return cmd;
}

int run_view(const ViewOptions& o) {
  Viewer::Settings settings;
  settings.render = render_settings(o.render);
  if (o.exit_after < 0) throw InputError("--exit-after: must be 0 or more");
  if (!o.screenshot.empty() && o.exit_after == 0) throw InputError("--screenshot: needs --exit-after N (the frame it shows)");
  if (o.fps) settings.fps = check_fps(*o.fps);
  if (const auto reason = refused_name(o.out)) throw InputError("--out: " + o.out + ": " + *reason);
  if (!std::filesystem::is_directory(o.out)) throw InputError("--out: " + o.out + ": not a folder");
  check_output_file("--record", o.record);
  check_output_file("--screenshot", o.screenshot);
  if (!o.play.empty()) settings.play = CameraPath::load(open_input(o.play, "paths"));
  settings.record_file = o.record;
  settings.out = o.out;
  settings.screenshot = o.screenshot;
  settings.hud = !o.no_hud;
  settings.full_hud = o.full_hud;
  settings.shadow_map_inset = o.shadow_map_inset;
  settings.aliasing_overlay = o.aliasing_overlay;

  // The scene before the window, so that a bad scene is bad input (exit 2) with or without a display.
  const auto load_start = Clock::now();
  const Scene scene = load_scene_option(o.scene);
  settings.scene_line = describe_scene(scene, ms_since(load_start) / 1000.0);
  std::cout << settings.scene_line << std::endl;
  settings.light = select_light(scene, o.scene.light);
  note_light_handed_over(settings.render.method, settings.light, o.scene.light);
  GlfwWindow window(settings.render.width, settings.render.height, "ecoview — " + scene.name);

  Viewer viewer(scene, settings, window);
  try {
    for (int frame = 0; !window.should_close() && (o.exit_after == 0 || frame < o.exit_after); ++frame) {
      viewer.frame(frame + 1 == o.exit_after);
      if (frame == 0) {
        std::cout << "view: first frame after " << static_cast<int>(ms_since(load_start) / 100.0) / 10.0
                  << " s; WASD and Q/E fly, drag to look, O orbits, R records, P writes the frame, Tab shows the full "
                     "HUD, H hides it, Esc quits" << std::endl;
      }
    }
  } catch (...) {
    viewer.finish();  // a path being recorded is kept
    throw;
  }
  viewer.finish();
  std::cout << viewer.summary() << " on " << window.description() << std::endl;
  return 0;
}

}  // namespace ecoview
