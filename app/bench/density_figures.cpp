#include "app/bench/density_figures.hpp"

#include "app/bench/image_similarity.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace ecoview {
namespace {

// Whether depth a is drawn and nearer than depth b (negative: nothing drawn).
bool in_front(float a, float b) { return a >= 0.0f && (b < 0.0f || a < b); }

// Depths of one surface in two renders: the same geometry, or the sampler's points of a plant in
// a render with and without the ground, which may choose a little differently.
constexpr float same_depth = 0.01f;

// Where the points or the polygons show an object drawn as points in the whole scene: it shows
// in the render of those objects, and the scene's render has the same depth there (no ground
// before it).
std::vector<bool> shown_by_either(const DensityRenders& renders) {
  const std::vector<bool> by_points = point_object_pixels(renders.points, renders.occluders);
  const std::vector<bool> by_polygons = point_object_pixels(renders.polygons, renders.occluders);
  auto same_surface = [](float object, float scene) { return std::abs(object - scene) <= same_depth * object; };
  std::vector<bool> either(by_points.size());
  for (std::size_t i = 0; i < either.size(); ++i) {
    either[i] = (by_points[i] && same_surface(renders.points.depth.samples[i], renders.points_in_scene.depth.samples[i])) ||
                (by_polygons[i] && same_surface(renders.polygons.depth.samples[i], renders.polygons_in_scene.depth.samples[i]));
  }
  return either;
}

}  // namespace

std::vector<bool> point_object_pixels(const RenderedFrame& polygons, const RenderedFrame& occluders) {
  std::vector<bool> pixels(polygons.depth.samples.size());
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = in_front(polygons.depth.samples[i], occluders.depth.samples[i]);
  return pixels;
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
  std::vector<std::size_t> nearest_first;
  for (std::size_t i = 0; i < covered.size(); ++i) {
    if (covered[i]) nearest_first.push_back(i);
  }
  std::stable_sort(nearest_first.begin(), nearest_first.end(), [&](std::size_t a, std::size_t b) { return depth[a] < depth[b]; });
  DensityFigures f;
  f.covered = nearest_first.size();
  if (f.covered == 0) return f;
  std::size_t holes = 0;
  double sum = 0.0, sum_squares = 0.0;
  for (std::size_t i : nearest_first) {
    holes += !in_front(renders.points.depth.samples[i], renders.occluders.depth.samples[i]);
    const double n = counts.samples[i];
    sum += n;
    sum_squares += n * n;
  }
  const auto n_covered = static_cast<double>(f.covered);
  f.holes = static_cast<double>(holes) / n_covered;
  f.pts_per_px = sum / n_covered;
  f.pts_per_px_cv = f.pts_per_px > 0.0 ? std::sqrt(std::max(0.0, sum_squares / n_covered - f.pts_per_px * f.pts_per_px)) / f.pts_per_px : 0.0;
  // Thirds of the pixels, not of the depth range: a few far pixels seen through a gap stretch the
  // range, and its outer thirds would hold next to nothing.
  std::array<double, 3> third_means{};
  for (std::size_t t = 0; t < 3; ++t) {
    const std::size_t begin = t * f.covered / 3, end = (t + 1) * f.covered / 3;
    double third_sum = 0.0;
    for (std::size_t j = begin; j < end; ++j) third_sum += counts.samples[nearest_first[j]];
    third_means[t] = end > begin ? third_sum / static_cast<double>(end - begin) : 0.0;
    f.third_depths[t] = depth[nearest_first[begin]];
  }
  f.third_depths[3] = depth[nearest_first.back()];
  f.pts_per_px_near = third_means[0];
  f.pts_per_px_middle = third_means[1];
  f.pts_per_px_far = third_means[2];
  return f;
}

FidelityFigures fidelity_figures(const DensityRenders& renders) {
  const std::vector<bool> either = shown_by_either(renders);
  return {psnr_over(either, renders.reference, renders.points_in_scene.color),
          ssim_over(either, renders.reference, renders.points_in_scene.color),
          psnr_over(either, renders.reference, renders.polygons_in_scene.color),
          ssim_over(either, renders.reference, renders.polygons_in_scene.color)};
}

}  // namespace ecoview
