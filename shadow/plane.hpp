#pragma once
#include <glm/glm.hpp>

namespace shadow {

// The plane dot(normal, p) = offset. Points with distance(p) <= 0 are inside; the normal points out.
struct Plane {
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  float offset = 0.0f;

  static Plane through(const glm::vec3& point, const glm::vec3& outward_normal) {
    const glm::vec3 n = glm::normalize(outward_normal);
    return {n, glm::dot(n, point)};
  }
  float distance(const glm::vec3& p) const { return glm::dot(normal, p) - offset; }
};

}  // namespace shadow
