#include "app/cli/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <utility>

namespace ecoview {

Progress::Progress(std::string what, std::size_t total)
    : Progress(std::move(what), total, std::cerr, ::isatty(STDERR_FILENO) != 0, Clock::now) {}

Progress::Progress(std::string what, std::size_t total, std::ostream& out, bool terminal, std::function<Clock::time_point()> now)
    : what_(std::move(what)), total_(total), out_(out), terminal_(terminal), now_(std::move(now)), start_(now_()),
      last_logged_(start_) {}

std::string Progress::line() const {
  const double elapsed = std::chrono::duration<double>(now_() - start_).count();
  const double per_item = elapsed / static_cast<double>(done_);
  char text[160];
  std::snprintf(text, sizeof text, " %zu/%zu, %.2f s each, %.0f s left", done_, total_, per_item,
                per_item * static_cast<double>(total_ - done_));
  return what_ + text;
}

void Progress::step() {
  ++done_;
  if (terminal_) {
    out_ << '\r' << line() << "   " << std::flush;
  } else if (now_() - last_logged_ >= log_interval) {
    last_logged_ = now_();
    out_ << line() << std::endl;
  }
}

void Progress::finish() {
  if (terminal_ && done_ > 0) out_ << '\n' << std::flush;
}

}  // namespace ecoview
