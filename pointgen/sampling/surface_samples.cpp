#include "pointgen/sampling/surface_samples.hpp"

#include "pointgen/random.hpp"

#include <algorithm>
#include <cmath>

namespace pointgen {
namespace {

float triangle_area(const TriangleMesh& m, std::size_t t) {
  const glm::vec3& a = m.positions[m.indices[t]];
  return 0.5f * glm::length(glm::cross(m.positions[m.indices[t + 1]] - a, m.positions[m.indices[t + 2]] - a));
}

// The radical inverse of i in `base`: i's digits mirrored about the point, in [0, 1).
double radical_inverse(std::uint64_t i, std::uint32_t base) {
  double inverse = 0.0, digit_weight = 1.0 / base;
  for (; i > 0; i /= base, digit_weight /= base) inverse += static_cast<double>(i % base) * digit_weight;
  return inverse;
}

// x + shift, wrapped into [0, 1).
double shifted(double x, double shift) {
  const double y = x + shift;
  return y >= 1.0 ? y - 1.0 : y;
}

}  // namespace

float surface_area(const TriangleMesh& mesh) {
  double area = 0.0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) area += triangle_area(mesh, t);
  return static_cast<float>(area);
}

std::vector<SurfaceSample> sample_surface(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed) {
  std::vector<double> cumulative;  // area up to and including each triangle
  cumulative.reserve(mesh.triangle_count());
  double total = 0.0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    total += triangle_area(mesh, t);
    cumulative.push_back(total);
  }
  std::vector<SurfaceSample> samples;
  if (total <= 0.0) return samples;
  samples.reserve(count);
  // The i-th point is Halton's (bases 2 and 3), shifted by a random offset per list
  // (Cranley-Patterson): the first coordinate picks a place along the triangles' cumulative area,
  // so the triangle that holds it and how far into that triangle's share it lies, the second where
  // across. The places of any prefix are within O(log n / n) of even, where independent draws
  // leave gaps that show as holes at thin blades and leaf edges (docs/point_density.md).
  Random rng(seed);
  const double shift_along = rng.uniform_double(), shift_across = rng.uniform_double();
  for (std::size_t i = 0; i < count; ++i) {
    const double pick = shifted(radical_inverse(i, 2), shift_along) * total;
    const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), pick);
    const std::size_t index = static_cast<std::size_t>(std::min<std::ptrdiff_t>(it - cumulative.begin(),
                                                                               static_cast<std::ptrdiff_t>(cumulative.size()) - 1));
    const std::size_t t = 3 * index;
    const double before = index > 0 ? cumulative[index - 1] : 0.0;
    const double share = cumulative[index] - before;
    // Uniform barycentric coordinates: fold the unit square onto the triangle.
    float u = share > 0.0 ? static_cast<float>(std::clamp((pick - before) / share, 0.0, 1.0)) : 0.0f;
    float v = static_cast<float>(shifted(radical_inverse(i, 3), shift_across));
    if (u + v > 1.0f) {
      u = 1.0f - u;
      v = 1.0f - v;
    }
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const float w = 1.0f - u - v;
    const glm::vec3 normal = w * mesh.normals[a] + u * mesh.normals[b] + v * mesh.normals[c];
    samples.push_back({w * mesh.positions[a] + u * mesh.positions[b] + v * mesh.positions[c],
                       glm::length(normal) > 0.0f ? glm::normalize(normal) : glm::vec3(0, 1, 0),
                       w * mesh.colors[a] + u * mesh.colors[b] + v * mesh.colors[c]});
  }
  return samples;
}

}  // namespace pointgen
