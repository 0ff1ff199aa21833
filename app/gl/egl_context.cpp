// Headless OpenGL through EGL: the device platform on a GPU (NVIDIA), Mesa's surfaceless platform
// otherwise. Rendering goes to framebuffer objects, so no surface is created.
#include "app/errors.hpp"
#include "app/gl/context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <vector>

namespace ecoview {
namespace {

bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + n, name)) {
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

[[noreturn]] void fail(const std::string& what) {
  throw RuntimeFailure("EGL backend: " + what + "; try --backend osmesa");
}

template <class F>
F egl_function(const char* name) {
  return reinterpret_cast<F>(eglGetProcAddress(name));
}

// A display on a GPU device, when EGL lists one that is not Mesa's software device.
EGLDisplay gpu_device_display(const char* client_extensions) {
  // NVIDIA's EGL names EGL_EXT_device_base, which holds enumeration and query, and not the two
  // extensions it was split into.
  const bool enumerates = has_extension(client_extensions, "EGL_EXT_device_enumeration") ||
                          has_extension(client_extensions, "EGL_EXT_device_base");
  if (!enumerates || !has_extension(client_extensions, "EGL_EXT_platform_device")) {
    return EGL_NO_DISPLAY;
  }
  auto query_devices = egl_function<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  auto device_string = egl_function<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  auto platform_display = egl_function<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  EGLint count = 0;
  if (!query_devices || !device_string || !platform_display || !query_devices(0, nullptr, &count)) {
    return EGL_NO_DISPLAY;
  }
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  query_devices(count, devices.data(), &count);
  for (EGLDeviceEXT device : devices) {
    if (has_extension(device_string(device, EGL_EXTENSIONS), "EGL_MESA_device_software")) continue;
    EGLDisplay display = platform_display(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
  }
  return EGL_NO_DISPLAY;
}

EGLDisplay surfaceless_display(const char* client_extensions) {
  if (!has_extension(client_extensions, "EGL_MESA_platform_surfaceless")) return EGL_NO_DISPLAY;
  auto platform_display = egl_function<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (!platform_display) return EGL_NO_DISPLAY;
  EGLDisplay display = platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) return EGL_NO_DISPLAY;
  return display;
}

void* egl_proc(void*, const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

class EglContext final : public GlContext {
 public:
  EglContext() {
    const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    platform_ = "EGL device";
    display_ = gpu_device_display(client_extensions);
    if (display_ == EGL_NO_DISPLAY) {
      platform_ = "EGL surfaceless";
      display_ = surfaceless_display(client_extensions);
    }
    if (display_ == EGL_NO_DISPLAY) fail("no GPU device and no Mesa surfaceless platform");
    if (!eglBindAPI(EGL_OPENGL_API)) fail("the display has no desktop OpenGL");

    EGLConfig config = nullptr;
    if (!has_extension(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
      const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
      EGLint found = 0;
      if (!eglChooseConfig(display_, wanted, &config, 1, &found) || found == 0) fail("no OpenGL config");
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) fail("cannot create an OpenGL 4.5 core context");
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) fail("cannot make the context current");
    renderer_ = load_gl_functions(&egl_proc, nullptr, "EGL backend");
  }

  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }

  std::string description() const override { return platform_ + ", " + renderer_; }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string platform_;
  std::string renderer_;
};

}  // namespace

std::unique_ptr<GlContext> create_egl_context() { return std::make_unique<EglContext>(); }

}  // namespace ecoview
