#include "app/cli/view_command.hpp"

#include "app/cli/options.hpp"
#include "app/errors.hpp"
#include "app/gl/glfw_window.hpp"
#include "app/render/renderer.hpp"

#include <chrono>

namespace ecoview {

CLI::App* add_view_command(CLI::App& app, ViewOptions& o) {
  CLI::App* cmd = app.add_subcommand("view", "Show a scene in a window (the scene's camera; flight controls "
                                             "are still to come)");
  cmd->add_option("--scene", o.scene, "Scene JSON file, or the name of a shipped scene");
  add_render_options(*cmd, o.render);
  cmd->add_option("--light", o.light, "Index of the scene light that shines and casts shadows")->capture_default_str();
  cmd->add_option("--memory-budget", o.memory_budget_gib, "Refuse scenes that would need more memory than this, in GiB")
      ->capture_default_str();
  cmd->add_option("--exit-after", o.exit_after, "Close after this many frames (0: when the window is closed)");
  return cmd;
}

int run_view(const ViewOptions& o) {
  const RenderSettings settings = render_settings(o.render);
  if (o.exit_after < 0) throw InputError("--exit-after: must be 0 or more");
  const Scene scene = load_scene_option(o.scene, o.memory_budget_gib);
  const shadow::Light& light = select_light(scene, o.light);

  GlfwWindow window(settings.width, settings.height, "ecoview — " + scene.name);
  Renderer renderer(scene, settings);
  const auto start = std::chrono::steady_clock::now();
  for (int frame = 0; !window.should_close() && (o.exit_after == 0 || frame < o.exit_after); ++frame) {
    renderer.render(scene.camera, light, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    const glm::ivec2 window_size = window.framebuffer_size();
    renderer.frame().present(window_size.x, window_size.y);
    window.swap_and_poll();
  }
  return 0;
}

}  // namespace ecoview
