#include "pointgen/sampling/silhouette.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace pointgen {
namespace {

constexpr int grid = 48;  // cells per side

// Area of the silhouette seen along the normal of the plane spanned by u and v: per cell of a grid
// over the bounds, the surface the samples stand for (each area / count, projected) gives the
// covered fraction 1 - e^-(projected / cell area), which counts thin twigs as what they hide.
float silhouette_area(const std::vector<SurfaceSample>& samples, float area, const Bounds& bounds, const glm::vec3& u,
                      const glm::vec3& v) {
  const glm::vec3 center = 0.5f * (bounds.min + bounds.max), half = 0.5f * (bounds.max - bounds.min);
  const glm::vec3 axis = glm::cross(u, v);
  // Half extents of the box along u and v.
  const float hu = glm::dot(glm::abs(u), half), hv = glm::dot(glm::abs(v), half);
  if (!(hu > 0.0f && hv > 0.0f)) return 0.0f;
  const float cell_area = 4.0f * hu * hv / (grid * grid);
  const float per_sample = area / static_cast<float>(samples.size());
  std::vector<float> projected(grid * grid, 0.0f);
  for (const SurfaceSample& s : samples) {
    const glm::vec3 p = s.position - center;
    const int x = std::clamp(static_cast<int>((glm::dot(p, u) / hu + 1.0f) * 0.5f * grid), 0, grid - 1);
    const int y = std::clamp(static_cast<int>((glm::dot(p, v) / hv + 1.0f) * 0.5f * grid), 0, grid - 1);
    projected[y * grid + x] += per_sample * std::abs(glm::dot(s.normal, axis));
  }
  float covered = 0.0f;
  for (float a : projected) covered += 1.0f - std::exp(-a / cell_area);
  return covered * cell_area;
}

}  // namespace

float mean_silhouette_area(const std::vector<SurfaceSample>& samples, float area, const Bounds& bounds) {
  if (samples.empty() || bounds.empty()) return 0.0f;
  const float r = 0.70710678f;
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  // (u, v) spanning the image plane of each direction: along x, z, the two diagonals, and from above.
  const std::array<std::array<glm::vec3, 2>, 5> planes = {{{glm::vec3(0, 0, 1), up},
                                                           {glm::vec3(1, 0, 0), up},
                                                           {glm::vec3(r, 0, -r), up},
                                                           {glm::vec3(r, 0, r), up},
                                                           {glm::vec3(1, 0, 0), glm::vec3(0, 0, 1)}}};
  float sum = 0.0f;
  for (const auto& plane : planes) sum += silhouette_area(samples, area, bounds, plane[0], plane[1]);
  return sum / static_cast<float>(planes.size());
}

}  // namespace pointgen
