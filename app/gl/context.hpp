#pragma once
#include <memory>
#include <string>

namespace ecoview {

// An OpenGL 4.5 core context, current on the calling thread once created. The GL functions are
// loaded through the backend's own GetProcAddress (glad), so one binary serves every backend;
// glad's function table is process-wide, so only one context exists at a time.
class GlContext {
 public:
  virtual ~GlContext() = default;
  // "EGL surfaceless", "OSMesa", "GLFW window", plus the GL renderer string.
  virtual std::string description() const = 0;
};

// "egl" (surfaceless on Mesa, the device platform where a GPU driver offers one) or "osmesa".
// Throws RuntimeFailure naming the backend and what to try instead.
std::unique_ptr<GlContext> create_headless_context(const std::string& backend);

// Whether this binary was built with the OSMesa backend.
bool osmesa_available();

// Loads the GL functions for the current context through `get_proc` and checks for GL 4.5 core;
// returns the GL renderer string. Throws RuntimeFailure naming `backend` otherwise.
using GetProc = void* (*)(void* user, const char* name);
std::string load_gl_functions(GetProc get_proc, void* user, const std::string& backend);

// The current context's GL_VERSION string, which names the driver's own version too ("4.5
// (Core Profile) Mesa 24.2.8").
std::string gl_version();

}  // namespace ecoview
