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
  Random rng(seed);
  for (std::size_t i = 0; i < count; ++i) {
    const double pick = rng.uniform_double() * total;
    const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), pick);
    const std::size_t t = 3 * static_cast<std::size_t>(std::min<std::ptrdiff_t>(it - cumulative.begin(),
                                                                               static_cast<std::ptrdiff_t>(cumulative.size()) - 1));
    // Uniform barycentric coordinates: fold the unit square onto the triangle.
    float u = rng.uniform(), v = rng.uniform();
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
