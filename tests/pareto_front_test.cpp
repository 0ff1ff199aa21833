// The Pareto front of frame time against error: which runs bench's summary keeps, for points
// whose front is known by construction.
#include "app/bench/pareto_front.hpp"

#include <gtest/gtest.h>

namespace ecoview::test {
namespace {

TEST(ParetoFront, KeepsOnlyMethodsNoOtherBeatsInBothTimeAndError) {
  const std::vector<TimeAndError> points = {
      {10.0, 0.5},  // 0: on the front
      {20.0, 0.2},  // 1: on the front
      {15.0, 0.6},  // 2: beaten by 0, faster and more accurate
      {30.0, 0.2},  // 3: beaten by 1, as accurate and faster
      {5.0, 0.9},   // 4: on the front, the fastest
      {40.0, 0.0},  // 5: on the front, the most accurate
      {5.0, 0.95},  // 6: beaten by 4, as fast and more accurate
  };
  EXPECT_EQ(pareto_front(points), (std::vector<std::size_t>{4, 0, 1, 5}));
}

TEST(ParetoFront, KeepsPointsEqualInBothTimeAndError) {
  EXPECT_EQ(pareto_front({{3.0, 0.1}, {3.0, 0.1}, {4.0, 0.2}}), (std::vector<std::size_t>{0, 1}));
}

BenchRun timed_run(const std::string& sweep, const std::string& scene, const std::string& method, double frame_ms, double err) {
  BenchRun run;
  run.params = {{"sweep", sweep}, {"scene", scene}, {"method", method}, {"shadow_size", 1024}};
  run.figures = {{"frame_ms", frame_ms}, {"err", err}};
  return run;
}

// Each scene has a front of its own, from its timed sweeps only: a stability run that would beat
// every other is no part of it.
TEST(ParetoFront, IsTakenPerSceneOverTheTimedSweeps) {
  const std::vector<BenchRun> runs = {timed_run("tradeoff", "field", "uniform", 10.0, 0.3),
                                      timed_run("tradeoff", "field", "psm", 12.0, 0.1),
                                      timed_run("tradeoff", "field", "lispsm", 13.0, 0.2),
                                      timed_run("stability", "field", "cascades", 1.0, 0.0),
                                      timed_run("scenes", "chess", "volumes", 50.0, 0.0),
                                      timed_run("scenes", "chess", "uniform", 60.0, 0.1)};
  const nlohmann::json fronts = pareto_fronts(runs);
  ASSERT_EQ(fronts.size(), 2u);
  std::vector<std::string> field, chess;
  for (const auto& point : fronts["field"]) field.push_back(point["method"]);
  for (const auto& point : fronts["chess"]) chess.push_back(point["method"]);
  ASSERT_EQ(field, (std::vector<std::string>{"uniform", "psm"}));
  EXPECT_EQ(chess, (std::vector<std::string>{"volumes"}));
  EXPECT_EQ(fronts["field"][1]["frame_ms"], 12.0);
  EXPECT_EQ(fronts["field"][1]["err"], 0.1);
}

}  // namespace
}  // namespace ecoview::test
