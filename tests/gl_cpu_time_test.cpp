// host_ms leaves out the CPU time spent inside GL calls and keeps the program's own.
#include "app/gl/context.hpp"
#include "app/gl/gl_cpu_time.hpp"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

namespace ecoview {
namespace {

// Work on this thread's CPU that no GL call does, for about `ms` of its CPU time.
double own_work(double ms) {
  const double start = thread_cpu_ms();
  double x = 0.0;
  for (long i = 0; thread_cpu_ms() - start < ms; ++i) x += std::sqrt(static_cast<double>(i));
  return x;
}

TEST(HostTime, LeavesOutWhatGlCallsSpendAndKeepsTheRest) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  // Reading a buffer back copies it on the calling thread: CPU time inside a GL call.
  std::vector<std::uint8_t> bytes(std::size_t{64} << 20, 7);
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferData(buffer, static_cast<GLsizeiptr>(bytes.size()), bytes.data(), GL_STATIC_READ);

  const double thread_start = thread_cpu_ms(), gl_start = gl_cpu_ms(), host_start = host_cpu_ms();
  for (int i = 0; i < 8; ++i) glGetNamedBufferSubData(buffer, 0, static_cast<GLsizeiptr>(bytes.size()), bytes.data());
  const double read_thread = thread_cpu_ms() - thread_start, read_gl = gl_cpu_ms() - gl_start;
  const double read_host = host_cpu_ms() - host_start;
  EXPECT_GT(read_thread, 5.0);  // 512 MiB copied
  EXPECT_GT(read_gl, 0.9 * read_thread);
  EXPECT_LT(read_host, 0.1 * read_thread);

  const double own_start = host_cpu_ms(), own_gl_start = gl_cpu_ms();
  EXPECT_GT(own_work(50.0), 0.0);
  EXPECT_GE(host_cpu_ms() - own_start, 50.0);
  EXPECT_EQ(gl_cpu_ms(), own_gl_start);
  glDeleteBuffers(1, &buffer);
}

// Timing a GL call reads the thread's clock twice; what those readings cost is not the program's own
// time (in a virtual machine a reading is a system call of about a microsecond).
TEST(HostTime, LeavesOutTheCostOfTimingTheGlCalls) {
  const std::unique_ptr<GlContext> context = create_headless_context("egl");
  constexpr int calls = 20000;
  GLint size = 0;
  const double thread_start = thread_cpu_ms(), host_start = host_cpu_ms();
  for (int i = 0; i < calls; ++i) glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
  const double thread_us = 1e3 * (thread_cpu_ms() - thread_start) / calls, host_us = 1e3 * (host_cpu_ms() - host_start) / calls;
  std::cout << "a call: " << thread_us << " µs, of it host " << host_us << " µs\n";
  EXPECT_GT(size, 0);
  EXPECT_LT(host_us, 0.2 * thread_us + 0.05);
}

}  // namespace
}  // namespace ecoview
