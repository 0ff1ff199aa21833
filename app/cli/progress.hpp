#pragma once
#include "app/clock.hpp"

#include <cstddef>
#include <functional>
#include <ostream>
#include <string>

namespace ecoview {

// How far a long command has come, on stderr: where that is a terminal, one line rewritten in place
// after each item; elsewhere (a log, CI, a batch job) a plain line every `log_interval`.
class Progress {
 public:
  static constexpr Clock::duration log_interval = std::chrono::seconds(10);

  Progress(std::string what, std::size_t total);
  // Writing to `out`, which is a terminal or not, at the times `now` gives.
  Progress(std::string what, std::size_t total, std::ostream& out, bool terminal, std::function<Clock::time_point()> now);
  void step();  // one item done
  void finish();

 private:
  std::string line() const;  // "capture: frame 3/30, 0.52 s each, 14 s left"

  std::string what_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::ostream& out_;
  bool terminal_;
  std::function<Clock::time_point()> now_;
  Clock::time_point start_;
  Clock::time_point last_logged_;
};

}  // namespace ecoview
