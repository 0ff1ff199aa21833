#include "app/errors.hpp"
#include "app/gl/context.hpp"

namespace ecoview {

std::unique_ptr<GlContext> create_egl_context();
#ifdef ECOVIEW_WITH_OSMESA
std::unique_ptr<GlContext> create_osmesa_context();
bool osmesa_library_found();
#endif

bool osmesa_available() {
#ifdef ECOVIEW_WITH_OSMESA
  return osmesa_library_found();
#else
  return false;
#endif
}

std::unique_ptr<GlContext> create_headless_context(const std::string& backend) {
  if (backend == "egl") return create_egl_context();
#ifdef ECOVIEW_WITH_OSMESA
  if (backend == "osmesa") return create_osmesa_context();
#else
  if (backend == "osmesa") {
    throw RuntimeFailure("OSMesa backend: this ecoview was built without OSMesa (libosmesa6-dev was not "
                         "found; Mesa 25.1 and later no longer ship it); use --backend egl");
  }
#endif
  throw InputError("--backend: unknown backend '" + backend + "' (known: egl, osmesa)");
}

}  // namespace ecoview
