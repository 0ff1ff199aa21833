#include "app/gl/gl_cpu_time.hpp"

#include <glad/gl.h>

#include <ctime>

namespace ecoview {
namespace {

thread_local double call_started_ms = 0.0;
thread_local double in_gl_ms = 0.0;

void before_call(const char*, GLADapiproc, int, ...) { call_started_ms = thread_cpu_ms(); }
void after_call(void*, const char*, GLADapiproc, int, ...) { in_gl_ms += thread_cpu_ms() - call_started_ms; }

}  // namespace

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

double gl_cpu_ms() { return in_gl_ms; }

// Replaces glad's own callbacks, which would call glGetError after every call.
void count_gl_cpu_time() {
  gladSetGLPreCallback(before_call);
  gladSetGLPostCallback(after_call);
}

}  // namespace ecoview
