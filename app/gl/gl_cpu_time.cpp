#include "app/gl/gl_cpu_time.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <ctime>

namespace ecoview {
namespace {

thread_local double call_started_ms = 0.0;
thread_local double in_gl_ms = 0.0;
thread_local double gl_calls = 0.0;
// The CPU time of one reading of the thread's clock. A GL call reads it twice, and about one
// reading's time falls outside what the two readings enclose: left uncounted it was the program's
// own time, 1.3 µs a call in a virtual machine whose clock reading is a system call, about 5 ms of
// a frame's 7 ms of host_ms on the ecosystem's path (some 4,000 GL calls a frame).
double clock_reading_ms = 0.0;

void before_call(const char*, GLADapiproc, int, ...) { call_started_ms = thread_cpu_ms(); }
void after_call(void*, const char*, GLADapiproc, int, ...) {
  in_gl_ms += thread_cpu_ms() - call_started_ms;
  gl_calls += 1.0;
}

// The least time a reading took over a few runs of many readings.
double time_clock_reading() {
  constexpr int readings = 2000;
  double least = INFINITY;
  for (int run = 0; run < 5; ++run) {
    const double start = thread_cpu_ms();
    for (int i = 1; i < readings; ++i) thread_cpu_ms();
    least = std::min(least, (thread_cpu_ms() - start) / readings);
  }
  return least;
}

}  // namespace

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

double gl_cpu_ms() { return in_gl_ms + gl_calls * clock_reading_ms; }

// Replaces glad's own callbacks, which would call glGetError after every call.
void count_gl_cpu_time() {
  if (clock_reading_ms == 0.0) clock_reading_ms = time_clock_reading();
  gladSetGLPreCallback(before_call);
  gladSetGLPostCallback(after_call);
}

}  // namespace ecoview
