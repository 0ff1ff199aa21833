#include "pointgen/sampling/point_count.hpp"

#include <algorithm>
#include <cmath>

namespace pointgen {

float points_needed(const PointDensity& density, float area, float depth, float distance, float facing) {
  const float z = std::max(depth, 1e-3f);
  const float d = std::max(distance, z);  // callers' rounding aside, depth <= distance
  return density.k * density.pixels_per_radian * density.pixels_per_radian * area * facing * d / (z * z * z);
}

glm::mat3 normal_moments(std::span<const glm::vec3> normals) {
  glm::mat3 sum(0.0f);
  for (const glm::vec3& n : normals) sum += glm::outerProduct(n, n);
  return normals.empty() ? sum : sum / static_cast<float>(normals.size());
}

float facing(const glm::mat3& moments, const glm::vec3& v) {
  if (!(moments[0][0] + moments[1][1] + moments[2][2] > 0.0f)) return 0.5f;
  return std::sqrt(std::max(glm::dot(v, moments * v), 0.0f));
}

}  // namespace pointgen
