#pragma once
#include "app/gl/gl_objects.hpp"

namespace ecoview::gl {

// GPU time of the commands between start() and stop(), from two timestamps, read by ms() when
// asked, so that nothing waits for the GPU in the middle of a frame. (A GL_TIME_ELAPSED query gave
// llvmpipe's clock since boot for a context's first shadow pass.)
class GpuTimer {
 public:
  void start() const { glQueryCounter(begin_.name(), GL_TIMESTAMP); }
  void stop() const { glQueryCounter(end_.name(), GL_TIMESTAMP); }
  // Waits for the commands up to stop() to finish.
  double ms() const {
    GLuint64 begin = 0, end = 0;
    glGetQueryObjectui64v(begin_.name(), GL_QUERY_RESULT, &begin);
    glGetQueryObjectui64v(end_.name(), GL_QUERY_RESULT, &end);
    return end > begin ? static_cast<double>(end - begin) * 1e-6 : 0.0;
  }

 private:
  Query begin_{GL_TIMESTAMP}, end_{GL_TIMESTAMP};
};

}  // namespace ecoview::gl
