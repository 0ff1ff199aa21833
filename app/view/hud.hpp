#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/gl/glfw_window.hpp"
#include "app/render/image.hpp"
#include "app/render/renderer.hpp"

#include <string>

namespace ecoview {

// What the HUD lets the user change while the viewer runs.
struct ViewControls {
  ShadowMethod method = ShadowMethod::uniform;
  int shadow_size = 2048;
  float k = 1.5f;
  shadow::Light light;
  bool shadow_map_inset = false;
  bool aliasing_overlay = false;
};

// What the HUD shows besides the renderer's own figures.
struct ViewStatus {
  double frame_ms = 0.0;      // wall time of the last frame, input to swap
  std::string scene;          // describe_scene's line
  glm::vec3 position{0.0f};   // the camera's
  float speed = 0.0f;         // flight speed, m/s
  bool orbiting = false;
  std::string activity;       // recording, playing, the last screenshot written
};

// The heads-up display of ecoview view (Dear ImGui): figures of the last frame, the live controls,
// an inset of the shadow map and the aliasing heat map over the frame.
class Hud {
 public:
  explicit Hud(const GlfwWindow& window);
  ~Hud();
  Hud(const Hud&) = delete;
  Hud& operator=(const Hud&) = delete;

  // Whether the last frame's panel took the keyboard or the mouse (typing, dragging a slider).
  bool wants_keyboard() const;
  bool wants_mouse() const;
  // Draws the panel over the window's default framebuffer; the user's edits go into `controls`.
  void draw(const ViewStatus& status, const Renderer& renderer, ViewControls& controls);

 private:
  void draw_panel(const ViewStatus& status, const Renderer& renderer, ViewControls& controls);
  void draw_shadow_map_inset(const Renderer& renderer);
  void draw_aliasing_overlay(const Renderer& renderer);

  // An RGBA texture for ImGui, made again when the image size changes.
  struct ImageTexture {
    gl::Texture texture{GL_TEXTURE_2D};
    int width = 0, height = 0;
    // `alpha` for every pixel but black ones, which become transparent when `black_clear`.
    void upload(const Image8& image, std::uint8_t alpha, bool black_clear);
  };
  ImageTexture inset_, overlay_;
};

}  // namespace ecoview
