#pragma once
#include "app/bench/results.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ecoview {

// bench --baseline OLD/results.json: each figure of this run beside the same figure of the same
// configuration in an earlier run, flagged where the change is beyond the run-to-run spread.

// One figure of one configuration in both runs, with each run's spread of it: a time's
// interquartile range over its repeated frames ("frame_ms_spread"), 0 for a figure without
// one (err, acne, leak, ...: deterministic).
struct FigureChange {
  nlohmann::json params;
  std::string figure;
  double old_value = 0.0, new_value = 0.0;
  double old_spread = 0.0, new_spread = 0.0;

  // The flag rule: |new − old| > old_spread + new_spread. Each median may sit anywhere within
  // its run's spread, so only a change larger than both spreads together is not noise; a
  // deterministic figure's spreads are 0, so any change of it is flagged.
  bool flagged() const;
};

struct BaselineComparison {
  std::vector<FigureChange> changes;  // every figure the two runs of a configuration share
  int runs_only_here = 0;             // configurations the baseline lacks
  int runs_only_in_baseline = 0;
};

// Runs are of the same configuration when their params are equal but for shadow_setup, which
// describes what the method chose rather than what was asked (and may change with the code).
BaselineComparison compare_to_baseline(const std::vector<BenchRun>& baseline, const std::vector<BenchRun>& runs);

// results.json's "baseline": the file, its machine's git commit and quick flag, the rule, the
// counts and every change with its spreads and flag.
nlohmann::json baseline_section(const std::string& file, const BenchResults& baseline, const BaselineComparison& comparison);

}  // namespace ecoview
