#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/gl/glfw_window.hpp"
#include "app/render/image.hpp"
#include "app/render/renderer.hpp"

#include <string>

namespace ecoview {

// What the HUD lets the user change while the viewer runs.
struct ViewControls {
  shadow::Method method;
  int shadow_size;
  float k;
  shadow::Light light;
  bool shadow_map_inset;
  bool aliasing_overlay;
  bool full_panel;  // the panel's details and controls, or its summary lines alone
};

// What the HUD shows besides the renderer's own figures.
struct ViewStatus {
  double frame_ms = 0.0;      // wall time of the last frame, input to swap
  std::string scene;          // describe_scene's line
  glm::vec3 position{0.0f};   // the camera's
  float speed = 0.0f;         // flight speed, m/s
  bool orbiting = false;
  std::string activity;       // recording, playing, the last file written, an error
};

// The heads-up display of ecoview view (Dear ImGui): a panel of the last frame's figures, folded to
// its summary lines or unfolded with the rest and the live controls; an inset of the shadow map and
// the aliasing heat map over the frame.
class Hud {
 public:
  // Installs ImGui's input callbacks on the window, chained to the window's own.
  explicit Hud(GlfwWindow& window);
  ~Hud();
  Hud(const Hud&) = delete;
  Hud& operator=(const Hud&) = delete;

  // Whether the last frame's panel took the keyboard or the mouse (a field or a slider in use).
  bool wants_keyboard() const;
  bool wants_mouse() const;
  // Draws the panel into the window's framebuffer; the user's edits go into `controls`.
  void draw(const ViewStatus& status, const Renderer& renderer, ViewControls& controls);

 private:
  void draw_panel(const ViewStatus& status, const Renderer& renderer, ViewControls& controls);
  void draw_summary(const ViewStatus& status, const Renderer& renderer, bool folded);
  void draw_details(const ViewStatus& status, const Renderer& renderer);
  void draw_controls(const Renderer& renderer, ViewControls& controls);
  void draw_shadow_map_inset(const Renderer& renderer);
  void draw_aliasing_overlay(const Renderer& renderer);

  gl::TextureView shadow_map_layer_;  // the map's first layer as a plain gray texture
  gl::Texture overlay_{GL_TEXTURE_2D};  // the aliasing heat map, RGBA
  glm::ivec2 overlay_size_{0};
};

}  // namespace ecoview
