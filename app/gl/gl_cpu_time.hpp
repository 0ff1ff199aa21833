#pragma once

namespace ecoview {

// The CPU time of the calling thread, in milliseconds.
double thread_cpu_ms();

// The CPU time the calling thread has spent inside GL calls, in milliseconds: the loader (glad,
// generated with --debug) calls back before and after each one, and each call also takes the time
// of one reading of the clock (count_gl_cpu_time measures it once). Counted from
// count_gl_cpu_time() on.
double gl_cpu_ms();
void count_gl_cpu_time();

// The calling thread's CPU time outside the GL driver: what host_ms adds up (docs/figures.md).
inline double host_cpu_ms() { return thread_cpu_ms() - gl_cpu_ms(); }

}  // namespace ecoview
