#include "app/bench/equal_error.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ecoview {
namespace {

BenchRun tradeoff(const char* method, int size, double err, double frame_ms) {
  BenchRun run;
  run.params = {{"sweep", "tradeoff"}, {"scene", "field"}, {"method", method}, {"shadow_size", size}};
  run.figures = {{"err", err}, {"frame_ms", frame_ms}};
  return run;
}

// A uniform map whose error halves and whose time doubles with each doubling of its side.
std::vector<BenchRun> uniform_maps() {
  return {tradeoff("uniform", 1024, 0.04, 20), tradeoff("uniform", 512, 0.08, 10), tradeoff("uniform", 4096, 0.01, 80),
          tradeoff("uniform", 2048, 0.02, 40)};
}

TEST(EqualError, TheUniformMapIsInterpolatedInLogErrorBetweenItsSizes) {
  std::vector<BenchRun> runs = uniform_maps();
  runs.push_back(tradeoff("psm", 1024, 0.02, 25));  // the uniform map's 2048² error
  runs.push_back(tradeoff("psm", 512, 0.03, 12));   // between its 1024² (4 %) and 2048² (2 %)
  const std::vector<BenchRun> found = equal_error_runs(runs, "field", "psm");
  ASSERT_EQ(found.size(), 2u);
  const BenchRun& small = found[0].params["shadow_size"] == 512 ? found[0] : found[1];
  const BenchRun& large = found[0].params["shadow_size"] == 1024 ? found[0] : found[1];
  EXPECT_EQ(large.params["bound"], "equal");
  EXPECT_NEAR(large.figures["equal_err_speedup"].get<double>(), 40.0 / 25.0, 1e-9);
  EXPECT_NEAR(large.figures["equal_err_texels"].get<double>(), 4.0, 1e-9);
  // log2(4 % / 3 %) of the way from 1024² to 2048²: side and time both grow by 2^t.
  const double t = std::log2(4.0 / 3.0);
  EXPECT_EQ(small.params["bound"], "equal");
  EXPECT_NEAR(small.figures["uniform_size"].get<double>(), 1024.0 * std::exp2(t), 1e-6);
  EXPECT_NEAR(small.figures["equal_err_speedup"].get<double>(), 20.0 * std::exp2(t) / 12.0, 1e-9);
  EXPECT_NEAR(small.figures["equal_err_texels"].get<double>(), std::pow(2.0 * std::exp2(t), 2.0), 1e-6);
}

TEST(EqualError, BeyondTheUniformMapsSizesItsNearestSizeIsABound) {
  std::vector<BenchRun> runs = uniform_maps();
  runs.push_back(tradeoff("psm", 1024, 0.005, 30));  // below the 4096² uniform map's 1 %
  runs.push_back(tradeoff("psm", 512, 0.1, 5));      // above the 512² one's 8 %
  for (const BenchRun& run : equal_error_runs(runs, "field", "psm")) {
    if (run.params["shadow_size"] == 1024) {
      EXPECT_EQ(run.params["bound"], "at least");
      EXPECT_NEAR(run.figures["equal_err_texels"].get<double>(), 16.0, 1e-9);
      EXPECT_NEAR(run.figures["equal_err_speedup"].get<double>(), 80.0 / 30.0, 1e-9);
    } else {
      EXPECT_EQ(run.params["bound"], "at most");
      EXPECT_NEAR(run.figures["equal_err_texels"].get<double>(), 1.0, 1e-9);
    }
  }
}

TEST(EqualError, OtherScenesAndMethodsAreLeftOut) {
  std::vector<BenchRun> runs = uniform_maps();
  runs.push_back(tradeoff("lispsm", 1024, 0.02, 25));
  BenchRun elsewhere = tradeoff("psm", 1024, 0.02, 25);
  elsewhere.params["scene"] = "ecosystem";
  runs.push_back(elsewhere);
  EXPECT_TRUE(equal_error_runs(runs, "field", "psm").empty());
  EXPECT_EQ(equal_error_runs(runs, "field", "lispsm").size(), 1u);
}

// The derived times carry the spreads of the times they come from, so that bench --baseline
// flags them no sooner than those: the uniform map's the larger of the two sizes it lies between,
// the speed-up's relative spread the sum of the two times' relative spreads.
TEST(EqualError, TheDerivedTimesCarryTheSpreadsOfTheTimesTheyComeFrom) {
  std::vector<BenchRun> runs = uniform_maps();
  for (BenchRun& run : runs) run.figures["frame_ms_spread"] = run.params["shadow_size"] == 1024 ? 2.0 : 4.0;
  BenchRun psm = tradeoff("psm", 1024, 0.03, 25);  // between the uniform 1024² (4 %) and 2048² (2 %)
  psm.figures["frame_ms_spread"] = 1.0;
  runs.push_back(psm);
  const std::vector<BenchRun> found = equal_error_runs(runs, "field", "psm");
  ASSERT_EQ(found.size(), 1u);
  const nlohmann::json& f = found[0].figures;
  EXPECT_EQ(f["uniform_frame_ms_spread"].get<double>(), 4.0);
  const double uniform_ms = f["uniform_frame_ms"].get<double>();
  EXPECT_NEAR(f["equal_err_speedup_spread"].get<double>(), uniform_ms / 25.0 * (4.0 / uniform_ms + 1.0 / 25.0), 1e-9);
}

}  // namespace
}  // namespace ecoview
