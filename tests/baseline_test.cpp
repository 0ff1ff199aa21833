// bench --baseline: an earlier results.json, written here by write_results, compared run by run
// with new runs whose changes the test sets on either side of the flag rule.
#include "app/bench/baseline.hpp"
#include "app/errors.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

namespace ecoview::test {
namespace {

BenchRun run_of(const std::string& method, const std::string& setup, double frame_ms, double spread, double err) {
  BenchRun run;
  run.params = {{"sweep", "tradeoff"}, {"scene", "field"}, {"method", method}, {"shadow_size", 512}, {"shadow_setup", setup}};
  run.figures = {{"frame_ms", frame_ms}, {"frame_ms_spread", spread}, {"err", err}};
  return run;
}

const FigureChange& change_of(const BaselineComparison& comparison, const std::string& method, const std::string& figure) {
  for (const FigureChange& c : comparison.changes) {
    if (c.params["method"] == method && c.figure == figure) return c;
  }
  throw std::runtime_error("no change of " + method + " " + figure);
}

TEST(Baseline, FlagsAChangeBeyondBothRunsSpreadsAndAnyChangeOfADeterministicFigure) {
  const TempDir dir;
  BenchResults old_results;
  old_results.machine = {{"git", "abc1234"}};
  old_results.runs = {run_of("psm", "camera moved back 1.0 m", 10.0, 1.0, 0.1),
                      run_of("uniform", "focused", 10.0, 0.5, 0.2),
                      run_of("cascades", "4 cascades", 10.0, 0.5, 0.2)};
  write_results(dir.path(), old_results);
  const BenchResults baseline = read_results(dir / "results.json");

  const std::vector<BenchRun> runs = {
      run_of("psm", "camera moved back 2.0 m", 11.9, 1.0, 0.1),  // 1.9 within 1 + 1; its setup's words changed
      run_of("uniform", "focused", 11.2, 0.5, 0.2000001),        // 1.2 beyond 0.5 + 0.5; err changed at all
      run_of("lispsm", "warped", 10.0, 0.5, 0.2)};               // new here
  const BaselineComparison comparison = compare_to_baseline(baseline.runs, runs);

  EXPECT_EQ(comparison.runs_only_here, 1);
  EXPECT_EQ(comparison.runs_only_in_baseline, 1);
  ASSERT_EQ(comparison.changes.size(), 4u);  // frame_ms and err of two runs; spreads are not figures to compare
  EXPECT_FALSE(change_of(comparison, "psm", "frame_ms").flagged());
  EXPECT_FALSE(change_of(comparison, "psm", "err").flagged());
  EXPECT_TRUE(change_of(comparison, "uniform", "frame_ms").flagged());
  EXPECT_TRUE(change_of(comparison, "uniform", "err").flagged());
  const FigureChange& psm = change_of(comparison, "psm", "frame_ms");
  EXPECT_EQ(psm.old_value, 10.0);
  EXPECT_EQ(psm.new_value, 11.9);
  EXPECT_EQ(psm.old_spread, 1.0);
  EXPECT_EQ(psm.new_spread, 1.0);
  EXPECT_EQ(change_of(comparison, "uniform", "err").old_spread + change_of(comparison, "uniform", "err").new_spread, 0.0);

  const nlohmann::json section = baseline_section("old/results.json", baseline, comparison);
  EXPECT_EQ(section["git"], "abc1234");
  int flagged = 0;
  for (const auto& c : section["changes"]) flagged += c["flagged"].get<bool>() ? 1 : 0;
  EXPECT_EQ(flagged, 2);
}

// The one line of an InputError: the file, then the field.
std::string refusal(const std::filesystem::path& file) {
  try {
    read_results(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Baseline, RefusesAFileThatIsNotBenchResultsNamingTheFileAndTheField) {
  const TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"camera": {}, "objects": []})", "machine: missing"},
      {R"({"machine": {}})", "runs: missing"},
      {R"({"machine": {}, "runs": {}})", "runs: expected an array"},
      {R"({"machine": {}, "runs": [{"params": {}}]})", "runs[0].figures: missing"},
      {R"({"machine": {}, "runs": [{"params": {}, "figures": {"err": 0.1}}, {"params": [], "figures": {}}]})", "runs[1].params: expected an object"},
      {R"({"machine": {}, "runs": [{"params": {}, "figures": {"err": "low"}}]})", "runs[0].figures.err: expected a number"},
      {R"({"machine": {}, "quick": 1, "runs": []})", "quick: expected true or false"},
      {"not json", "invalid JSON"}};
  for (const auto& [text, field] : cases) {
    write_text(dir / "old.json", text);
    const std::string message = refusal(dir / "old.json");
    EXPECT_EQ(message.rfind((dir / "old.json").string(), 0), 0u) << message;
    EXPECT_NE(message.find(field), std::string::npos) << message;
  }
  EXPECT_NE(refusal(dir / "absent.json").find((dir / "absent.json").string()), std::string::npos);
}

}  // namespace
}  // namespace ecoview::test
