#pragma once
#include "app/gl/context.hpp"

#include <glm/glm.hpp>

#include <vector>

struct GLFWwindow;

namespace ecoview {

// A window with an OpenGL 4.5 core context, for `ecoview view`; not resizable, as the frame has a
// fixed size (--size).
class GlfwWindow final : public GlContext {
 public:
  // Throws RuntimeFailure (pointing to `ecoview capture`) when no display can be opened.
  GlfwWindow(int width, int height, const std::string& title);
  ~GlfwWindow() override;
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  std::string description() const override { return "GLFW window, " + renderer_; }
  bool should_close() const;
  void close();
  void swap_and_poll();
  glm::ivec2 framebuffer_size() const;
  GLFWwindow* handle() const { return window_; }

  // Input since the last swap_and_poll: keys pressed (GLFW key codes, in order) and scrolling.
  const std::vector<int>& keys_pressed() const { return keys_pressed_; }
  double scrolled() const { return scrolled_; }
  bool key_down(int key) const;
  bool mouse_button_down(int button) const;
  glm::dvec2 cursor() const;

 private:
  static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void on_scroll(GLFWwindow* window, double x, double y);

  GLFWwindow* window_ = nullptr;
  std::string renderer_;
  std::vector<int> keys_pressed_;
  double scrolled_ = 0.0;
};

}  // namespace ecoview
