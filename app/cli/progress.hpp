#pragma once
#include <chrono>
#include <string>

namespace ecoview {

// A progress line on stderr, rewritten in place, shown only when stderr is a terminal.
class Progress {
 public:
  Progress(std::string what, std::size_t total);
  void step();  // one item done
  void finish();

 private:
  std::string what_;
  std::size_t total_;
  std::size_t done_ = 0;
  bool terminal_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace ecoview
