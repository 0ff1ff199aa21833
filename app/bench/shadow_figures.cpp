#include "app/bench/shadow_figures.hpp"

#include "shadow/aliasing.hpp"

#include <algorithm>
#include <cmath>

namespace ecoview {
namespace {

bool shadowed(std::uint8_t visibility) { return visibility < 128; }
bool surface(float depth) { return depth > 0.0f; }

double ratio(std::size_t a, std::size_t b) { return b ? static_cast<double>(a) / static_cast<double>(b) : 0.0; }

bool changed(const Image8& before, const Image8& after, std::size_t i) { return shadowed(before.samples[i]) != shadowed(after.samples[i]); }

// The fraction of the surface pixels at which `counts` holds.
template <typename Counts>
double surface_share(const Image<float>& depth, Counts counts) {
  std::size_t pixels = 0, counted = 0;
  for (std::size_t i = 0; i < depth.samples.size(); ++i) {
    if (!surface(depth.samples[i])) continue;
    ++pixels;
    counted += counts(i);
  }
  return ratio(counted, pixels);
}

}  // namespace

double alias_percentile(const Image<float>& aliasing, const Image8& visibility, float fraction) {
  std::vector<float> lit;
  for (std::size_t i = 0; i < aliasing.samples.size(); ++i) {
    if (aliasing.samples[i] > 0.0f && visibility.samples[i] >= 128) lit.push_back(aliasing.samples[i]);
  }
  return shadow::percentile(std::move(lit), fraction);
}

ShadowErrors shadow_errors(const Image8& visibility, const Image8& reference, const Image<float>& depth) {
  float nearest = INFINITY, farthest = 0.0f;
  for (float d : depth.samples) {
    if (!surface(d)) continue;
    nearest = std::min(nearest, d);
    farthest = std::max(farthest, d);
  }
  const float near_limit = nearest + 0.2f * (farthest - nearest);
  std::size_t pixels = 0, acne = 0, leak = 0, near_pixels = 0, near_errors = 0;
  for (std::size_t i = 0; i < depth.samples.size(); ++i) {
    if (!surface(depth.samples[i])) continue;
    ++pixels;
    const bool frame = shadowed(visibility.samples[i]), exact = shadowed(reference.samples[i]);
    acne += frame && !exact;
    leak += !frame && exact;
    if (depth.samples[i] <= near_limit) {
      ++near_pixels;
      near_errors += frame != exact;
    }
  }
  return {ratio(acne + leak, pixels), ratio(near_errors, near_pixels), ratio(acne, pixels), ratio(leak, pixels)};
}

double changed_shadow(const Image8& before, const Image8& after, const Image<float>& depth) {
  return surface_share(depth, [&](std::size_t i) { return changed(before, after, i); });
}

double temporal_err(const Image8& before, const Image8& after, const Image8& reference_before, const Image8& reference_after,
                    const Image<float>& depth) {
  return surface_share(depth, [&](std::size_t i) { return changed(before, after, i) != changed(reference_before, reference_after, i); });
}

}  // namespace ecoview
