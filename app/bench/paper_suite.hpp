#pragma once
#include "app/cli/options.hpp"

namespace ecoview {

// `ecoview bench --suite paper`: the figures of the perspective shadow map paper (Stamminger and
// Drettakis 2002: Figs. 1, 8, 9, 10), the uniform / DPSM / IPSM comparison of Vanek et al. (2011,
// Table 1) and the overhead light and inverted light's bias of a PSM implementation note (2002),
// each rendered, timed and measured against the exact reference in ecoview's own scenes, into
// `options.out`: results.json and results.csv (sweep "paper", param "figure"), images/paper_*.png
// and report.html. --quick: one frame a configuration and the courtyard for the ecosystem.
void run_paper_suite(const BenchmarkOptions& options);

}  // namespace ecoview
