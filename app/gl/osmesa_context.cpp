// Headless OpenGL through Mesa's OSMesa, the fallback where EGL is missing. Built only when
// libOSMesa is found (Mesa removed it in 25.1).
#include "app/errors.hpp"
#include "app/gl/context.hpp"

#include <glad/gl.h>  // before osmesa.h, which then finds the GL types defined

#include <GL/osmesa.h>

#include <vector>

namespace ecoview {
namespace {

void* osmesa_proc(void*, const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext() {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr) {
      throw RuntimeFailure("OSMesa backend: cannot create an OpenGL 4.5 core context; try --backend egl");
    }
    // Rendering goes to framebuffer objects; the default buffer only has to exist.
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, side, side)) {
      OSMesaDestroyContext(context_);
      throw RuntimeFailure("OSMesa backend: cannot make the context current; try --backend egl");
    }
    renderer_ = load_gl_functions(&osmesa_proc, nullptr, "OSMesa backend");
  }
  ~OsmesaContext() override { OSMesaDestroyContext(context_); }

  std::string description() const override { return "OSMesa, " + renderer_; }

 private:
  static constexpr int side = 16;
  std::vector<unsigned char> buffer_ = std::vector<unsigned char>(side * side * 4);
  OSMesaContext context_ = nullptr;
  std::string renderer_;
};

}  // namespace

std::unique_ptr<GlContext> create_osmesa_context() { return std::make_unique<OsmesaContext>(); }

}  // namespace ecoview
