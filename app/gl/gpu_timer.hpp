#pragma once
#include "app/gl/gl_objects.hpp"

namespace ecoview::gl {

// GPU time of the commands between start() and stop_ms(), from two timestamps. (A GL_TIME_ELAPSED
// query gave llvmpipe's clock since boot for a context's first shadow pass.)
class GpuTimer {
 public:
  void start() const { glQueryCounter(begin_.name(), GL_TIMESTAMP); }
  // Waits for the commands to finish.
  double stop_ms() const {
    glQueryCounter(end_.name(), GL_TIMESTAMP);
    GLuint64 begin = 0, end = 0;
    glGetQueryObjectui64v(begin_.name(), GL_QUERY_RESULT, &begin);
    glGetQueryObjectui64v(end_.name(), GL_QUERY_RESULT, &end);
    return end > begin ? static_cast<double>(end - begin) * 1e-6 : 0.0;
  }

 private:
  Query begin_{GL_TIMESTAMP}, end_{GL_TIMESTAMP};
};

}  // namespace ecoview::gl
