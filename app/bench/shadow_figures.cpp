#include "app/bench/shadow_figures.hpp"

#include <algorithm>

namespace ecoview {

double alias_p95(const Image<float>& aliasing, const Image8& visibility) {
  std::vector<float> lit;
  for (std::size_t i = 0; i < aliasing.samples.size(); ++i) {
    if (aliasing.samples[i] > 0.0f && visibility.samples[i] >= 128) lit.push_back(aliasing.samples[i]);
  }
  if (lit.empty()) return 0.0;
  const auto p95 = lit.begin() + static_cast<std::ptrdiff_t>(0.95 * static_cast<double>(lit.size() - 1));
  std::nth_element(lit.begin(), p95, lit.end());
  return *p95;
}

}  // namespace ecoview
