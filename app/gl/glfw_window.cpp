#include "app/gl/glfw_window.hpp"

#include "app/errors.hpp"

#include <GLFW/glfw3.h>

namespace ecoview {
namespace {

void* glfw_proc(void*, const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

}  // namespace

GlfwWindow::GlfwWindow(int width, int height, const std::string& title) {
  if (!glfwInit()) {
    throw RuntimeFailure("GLFW backend: cannot open a display (is DISPLAY set?); for frames without a "
                         "display use `ecoview capture`");
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    glfwTerminate();
    throw RuntimeFailure("GLFW backend: cannot create a window with OpenGL 4.5 core; for frames "
                         "without a window use `ecoview capture`");
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(0);
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, &GlfwWindow::on_key);
  glfwSetScrollCallback(window_, &GlfwWindow::on_scroll);
  try {
    renderer_ = load_gl_functions(&glfw_proc, nullptr, "GLFW backend");
  } catch (...) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw;
  }
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool GlfwWindow::should_close() const { return glfwWindowShouldClose(window_) != 0; }

void GlfwWindow::close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void GlfwWindow::swap_and_poll() {
  glfwSwapBuffers(window_);
  keys_pressed_.clear();
  scrolled_ = 0.0;
  glfwPollEvents();
}

void GlfwWindow::on_key(GLFWwindow* window, int key, int, int action, int) {
  if (action == GLFW_PRESS) static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window))->keys_pressed_.push_back(key);
}

void GlfwWindow::on_scroll(GLFWwindow* window, double, double y) {
  static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window))->scrolled_ += y;
}

bool GlfwWindow::key_down(int key) const { return glfwGetKey(window_, key) == GLFW_PRESS; }

bool GlfwWindow::mouse_button_down(int button) const { return glfwGetMouseButton(window_, button) == GLFW_PRESS; }

glm::dvec2 GlfwWindow::cursor() const {
  glm::dvec2 position;
  glfwGetCursorPos(window_, &position.x, &position.y);
  return position;
}

glm::ivec2 GlfwWindow::framebuffer_size() const {
  glm::ivec2 size;
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

}  // namespace ecoview
