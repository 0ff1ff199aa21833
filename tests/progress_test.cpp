// Progress where stderr is a terminal and where it is not (a log, CI), on an injected clock.
#include "app/cli/progress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace ecoview::test {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// 40 items of 3 s each: a line at the first item done 10 s or more after the last line, that is
// every 4th item (12 s); each says how many are done, the time an item takes and the time left.
TEST(Progress, WithoutATerminalItWritesAPlainLineEveryTenSeconds) {
  Clock::time_point now{};
  std::ostringstream out;
  Progress progress("capture: frame", 40, out, false, [&] { return now; });
  std::vector<std::string> expected;
  for (int done = 1; done <= 40; ++done) {
    now += std::chrono::seconds(3);
    progress.step();
    if (done % 4 == 0) {
      char line[100];
      std::snprintf(line, sizeof line, "capture: frame %d/40, 3.00 s each, %d s left", done, 3 * (40 - done));
      expected.push_back(line);
    }
  }
  progress.finish();
  EXPECT_EQ(out.str().find('\r'), std::string::npos);
  EXPECT_EQ(lines_of(out.str()), expected);
}

TEST(Progress, WithoutATerminalARunShorterThanTenSecondsWritesNothing) {
  Clock::time_point now{};
  std::ostringstream out;
  Progress progress("density: run", 9, out, false, [&] { return now; });
  for (int done = 1; done <= 9; ++done) {
    now += std::chrono::seconds(1);
    progress.step();
  }
  progress.finish();
  EXPECT_EQ(out.str(), "");
}

// On a terminal the line is rewritten after every item and ended when the work is.
TEST(Progress, OnATerminalOneLineIsRewrittenAfterEachItem) {
  Clock::time_point now{};
  std::ostringstream out;
  Progress progress("bench: run", 3, out, true, [&] { return now; });
  for (int done = 1; done <= 3; ++done) {
    now += std::chrono::milliseconds(500);
    progress.step();
  }
  progress.finish();
  const std::string text = out.str();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\r'), 3);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1);
  EXPECT_NE(text.find("\rbench: run 3/3, 0.50 s each, 0 s left"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
}

}  // namespace
}  // namespace ecoview::test
