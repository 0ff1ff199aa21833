#pragma once
#include "app/gl/context.hpp"

#include <glm/glm.hpp>

struct GLFWwindow;

namespace ecoview {

// A window with an OpenGL 4.5 core context, for `ecoview view`.
class GlfwWindow final : public GlContext {
 public:
  // Throws RuntimeFailure (pointing to `ecoview capture`) when no display can be opened.
  GlfwWindow(int width, int height, const std::string& title);
  ~GlfwWindow() override;
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  std::string description() const override { return "GLFW window, " + renderer_; }
  bool should_close() const;
  void swap_and_poll();
  glm::ivec2 framebuffer_size() const;

 private:
  GLFWwindow* window_ = nullptr;
  std::string renderer_;
};

}  // namespace ecoview
