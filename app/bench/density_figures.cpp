#include "app/bench/density_figures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ecoview {
namespace {

// Whether depth a is drawn and nearer than depth b (negative: nothing drawn).
bool in_front(float a, float b) { return a >= 0.0f && (b < 0.0f || a < b); }

}  // namespace

std::vector<bool> point_object_pixels(const RenderedFrame& polygons, const RenderedFrame& occluders) {
  std::vector<bool> pixels(polygons.depth.samples.size());
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = in_front(polygons.depth.samples[i], occluders.depth.samples[i]);
  return pixels;
}

double psnr_over(const std::vector<bool>& pixels, const Image8& reference, const Image8& image) {
  double squared_error = 0.0;
  std::size_t samples = 0;
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    if (!pixels[i]) continue;
    for (std::size_t c = 3 * i; c < 3 * i + 3; ++c) {
      const double e = static_cast<double>(reference.samples[c]) - static_cast<double>(image.samples[c]);
      squared_error += e * e;
    }
    samples += 3;
  }
  if (samples == 0) return 0.0;
  return squared_error > 0.0 ? 10.0 * std::log10(255.0 * 255.0 * static_cast<double>(samples) / squared_error) : 99.0;
}

Image8 coverage_map(const DensityRenders& renders) {
  const std::vector<bool> covered = point_object_pixels(renders.polygons, renders.occluders);
  Image8 map = renders.polygons.color;
  for (std::size_t i = 0; i < covered.size(); ++i) {
    std::uint8_t* rgb = &map.samples[3 * i];
    if (!covered[i]) {
      for (int c = 0; c < 3; ++c) rgb[c] = static_cast<std::uint8_t>(rgb[c] / 3);
    } else if (!in_front(renders.points.depth.samples[i], renders.occluders.depth.samples[i])) {
      rgb[0] = 255, rgb[1] = 0, rgb[2] = 0;
    }
  }
  return map;
}

DensityFigures density_figures(const DensityRenders& renders, const Image<std::uint32_t>& counts) {
  const std::vector<bool> covered = point_object_pixels(renders.polygons, renders.occluders);
  const std::vector<float>& depth = renders.polygons.depth.samples;
  DensityFigures f;
  float near = std::numeric_limits<float>::max(), far = 0.0f;
  for (std::size_t i = 0; i < covered.size(); ++i) {
    if (!covered[i]) continue;
    near = std::min(near, depth[i]);
    far = std::max(far, depth[i]);
  }
  std::size_t holes = 0;
  double sum = 0.0, sum_squares = 0.0;
  std::array<double, 3> third_points{};
  for (std::size_t i = 0; i < covered.size(); ++i) {
    if (!covered[i]) continue;
    ++f.covered;
    holes += !in_front(renders.points.depth.samples[i], renders.occluders.depth.samples[i]);
    const double n = counts.samples[i];
    sum += n;
    sum_squares += n * n;
    const auto third = static_cast<std::size_t>(std::min(2.0f, 3.0f * (depth[i] - near) / std::max(far - near, 1e-6f)));
    third_points[third] += n;
    ++f.third_pixels[third];
  }
  if (f.covered == 0) return f;
  const auto n_covered = static_cast<double>(f.covered);
  f.holes = static_cast<double>(holes) / n_covered;
  f.psnr = psnr_over(covered, renders.polygons.color, renders.points.color);
  f.pts_per_px = sum / n_covered;
  f.pts_per_px_cv = f.pts_per_px > 0.0 ? std::sqrt(std::max(0.0, sum_squares / n_covered - f.pts_per_px * f.pts_per_px)) / f.pts_per_px : 0.0;
  const auto mean_in = [&](int third) {
    return f.third_pixels[third] > 0 ? third_points[third] / static_cast<double>(f.third_pixels[third]) : 0.0;
  };
  f.pts_per_px_near = mean_in(0);
  f.pts_per_px_middle = mean_in(1);
  f.pts_per_px_far = mean_in(2);
  return f;
}

}  // namespace ecoview
