// Headless OpenGL through Mesa's OSMesa, the fallback where EGL is missing. Built only where
// osmesa.h is found (Mesa removed OSMesa in 25.1), and opened when first asked for rather than
// linked: libOSMesa brings Mesa's whole software driver (LLVM), which a machine with a GPU driver
// neither has nor needs (scripts/gpu_bundle.sh).
#include "app/errors.hpp"
#include "app/gl/context.hpp"

#include <glad/gl.h>  // before osmesa.h, which then finds the GL types defined

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <vector>

namespace ecoview {
namespace {

// The OSMesa functions ecoview calls, from libOSMesa; none where it cannot be opened.
struct OsmesaLibrary {
  decltype(&OSMesaCreateContextAttribs) create_context = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
  decltype(&OSMesaDestroyContext) destroy_context = nullptr;
};

template <class F>
void find(void* library, const char* name, F& function) {
  function = reinterpret_cast<F>(dlsym(library, name));
}

const OsmesaLibrary* osmesa_library() {
  static const OsmesaLibrary* const opened = []() -> const OsmesaLibrary* {
    void* library = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
    if (library == nullptr) return nullptr;
    static OsmesaLibrary functions;
    find(library, "OSMesaCreateContextAttribs", functions.create_context);
    find(library, "OSMesaMakeCurrent", functions.make_current);
    find(library, "OSMesaGetProcAddress", functions.get_proc_address);
    find(library, "OSMesaDestroyContext", functions.destroy_context);
    if (!functions.create_context || !functions.make_current || !functions.get_proc_address || !functions.destroy_context) return nullptr;
    return &functions;
  }();
  return opened;
}

void* osmesa_proc(void*, const char* name) { return reinterpret_cast<void*>(osmesa_library()->get_proc_address(name)); }

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext() : osmesa_(*osmesa_library()) {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    context_ = osmesa_.create_context(attributes, nullptr);
    if (context_ == nullptr) {
      throw RuntimeFailure("OSMesa backend: cannot create an OpenGL 4.5 core context; try --backend egl");
    }
    // Rendering goes to framebuffer objects; the default buffer only has to exist.
    if (!osmesa_.make_current(context_, buffer_.data(), GL_UNSIGNED_BYTE, side, side)) {
      osmesa_.destroy_context(context_);
      throw RuntimeFailure("OSMesa backend: cannot make the context current; try --backend egl");
    }
    renderer_ = load_gl_functions(&osmesa_proc, nullptr, "OSMesa backend");
  }
  ~OsmesaContext() override { osmesa_.destroy_context(context_); }

  std::string description() const override { return "OSMesa, " + renderer_; }

 private:
  static constexpr int side = 16;
  const OsmesaLibrary& osmesa_;
  std::vector<unsigned char> buffer_ = std::vector<unsigned char>(side * side * 4);
  OSMesaContext context_ = nullptr;
  std::string renderer_;
};

}  // namespace

bool osmesa_library_found() { return osmesa_library() != nullptr; }

std::unique_ptr<GlContext> create_osmesa_context() {
  if (!osmesa_library_found()) {
    throw RuntimeFailure("OSMesa backend: libOSMesa.so.8 cannot be opened (install libosmesa6); use --backend egl");
  }
  return std::make_unique<OsmesaContext>();
}

}  // namespace ecoview
