// A time's spread over its repeated frames, which bench --baseline allows a time before it flags
// a change: the interquartile range, for repeats whose quartiles are known by construction.
#include "app/bench/frame_timing.hpp"

#include <gtest/gtest.h>

namespace ecoview::test {
namespace {

TEST(FrameTiming, SpreadIsTheDistanceBetweenTheMediansOfTheFastAndTheSlowHalves) {
  EXPECT_EQ(interquartile_range({8, 1, 7, 2, 6, 3, 5, 4}), 6.5 - 2.5);  // halves 1-4 and 5-8
  EXPECT_EQ(interquartile_range({4, 100, 3, 1, 2}), (4 + 100) / 2.0 - (1 + 2) / 2.0);  // the middle 3 in neither
}

TEST(FrameTiming, OneFrameHasNoSpread) {
  EXPECT_EQ(interquartile_range({5.0}), 0.0);
  EXPECT_EQ(interquartile_range({}), 0.0);
}

}  // namespace
}  // namespace ecoview::test
