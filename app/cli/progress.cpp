#include "app/cli/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace ecoview {

Progress::Progress(std::string what, std::size_t total)
    : what_(std::move(what)), total_(total), terminal_(::isatty(STDERR_FILENO) != 0) {}

void Progress::step() {
  ++done_;
  if (!terminal_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double per_item = elapsed / static_cast<double>(done_);
  std::fprintf(stderr, "\r%s %zu/%zu  %.2f s each, %.0f s left   ", what_.c_str(), done_, total_, per_item,
               per_item * static_cast<double>(total_ - done_));
  std::fflush(stderr);
}

void Progress::finish() {
  if (terminal_ && done_ > 0) std::fputc('\n', stderr);
}

}  // namespace ecoview
