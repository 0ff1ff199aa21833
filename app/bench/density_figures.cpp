#include "app/bench/density_figures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ecoview {

double psnr_over_covered(const RenderedFrame& reference, const Image8& image) {
  double squared_error = 0.0;
  std::size_t samples = 0;
  for (std::size_t i = 0; i < reference.depth.samples.size(); ++i) {
    if (reference.depth.samples[i] < 0.0f) continue;
    for (std::size_t c = 3 * i; c < 3 * i + 3; ++c) {
      const double e = static_cast<double>(reference.color.samples[c]) - static_cast<double>(image.samples[c]);
      squared_error += e * e;
    }
    samples += 3;
  }
  if (samples == 0) return 0.0;
  return squared_error > 0.0 ? 10.0 * std::log10(255.0 * 255.0 * static_cast<double>(samples) / squared_error) : 99.0;
}

DensityFigures density_figures(const RenderedFrame& polygons, const RenderedFrame& points,
                               const Image<std::uint32_t>& counts) {
  DensityFigures f;
  float near = std::numeric_limits<float>::max(), far = 0.0f;
  for (float d : polygons.depth.samples) {
    if (d < 0.0f) continue;
    near = std::min(near, d);
    far = std::max(far, d);
  }
  std::size_t holes = 0;
  double sum = 0.0, sum_squares = 0.0;
  std::array<double, 3> third_points{}, third_pixels{};
  for (std::size_t i = 0; i < polygons.depth.samples.size(); ++i) {
    const float d = polygons.depth.samples[i];
    if (d < 0.0f) continue;
    ++f.covered;
    holes += points.depth.samples[i] < 0.0f;
    const double n = counts.samples[i];
    sum += n;
    sum_squares += n * n;
    const auto third = static_cast<std::size_t>(std::min(2.0f, 3.0f * (d - near) / std::max(far - near, 1e-6f)));
    third_points[third] += n;
    third_pixels[third] += 1.0;
  }
  if (f.covered == 0) return f;
  const auto covered = static_cast<double>(f.covered);
  f.holes = static_cast<double>(holes) / covered;
  f.psnr = psnr_over_covered(polygons, points.color);
  f.pts_per_px = sum / covered;
  f.pts_per_px_cv = f.pts_per_px > 0.0 ? std::sqrt(std::max(0.0, sum_squares / covered - f.pts_per_px * f.pts_per_px)) / f.pts_per_px : 0.0;
  f.pts_per_px_near = third_pixels[0] > 0 ? third_points[0] / third_pixels[0] : 0.0;
  f.pts_per_px_middle = third_pixels[1] > 0 ? third_points[1] / third_pixels[1] : 0.0;
  f.pts_per_px_far = third_pixels[2] > 0 ? third_points[2] / third_pixels[2] : 0.0;
  return f;
}

}  // namespace ecoview
