#include "app/errors.hpp"
#include "app/gl/context.hpp"
#include "app/gl/gl_cpu_time.hpp"

#include <glad/gl.h>

namespace ecoview {

std::string load_gl_functions(GetProc get_proc, void* user, const std::string& backend) {
  const int version = gladLoadGLUserPtr(reinterpret_cast<GLADuserptrloadfunc>(get_proc), user);
  if (version == 0) {
    throw RuntimeFailure(backend + ": cannot load the OpenGL functions; try another --backend");
  }
  if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 45) {
    throw RuntimeFailure(backend + ": the context offers OpenGL " + std::to_string(GLAD_VERSION_MAJOR(version)) +
                         "." + std::to_string(GLAD_VERSION_MINOR(version)) +
                         ", ecoview needs 4.5 core; try another --backend or a newer driver");
  }
  if (!GLAD_GL_ARB_indirect_parameters) {
    throw RuntimeFailure(backend + ": the driver lacks GL_ARB_indirect_parameters (OpenGL 4.6's draw counts), which ecoview "
                         "needs; try another --backend or a newer driver");
  }
  count_gl_cpu_time();
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer ? renderer : "unknown renderer";
}

std::string gl_version() {
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return version ? version : "unknown";
}

}  // namespace ecoview
