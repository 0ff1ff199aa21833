#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace pointgen {

// Axis-aligned bounds; empty until a point is added.
struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{std::numeric_limits<float>::lowest()};

  bool empty() const { return min.x > max.x; }
  void add(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
};

// An indexed triangle mesh in object space with per-vertex normals and linear RGB colours
// (multiplied with the colour of each instance).
struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec3> colors;
  std::vector<std::uint32_t> indices;  // three per triangle

  std::size_t triangle_count() const { return indices.size() / 3; }
  Bounds bounds() const;
  // Appends `other`, its vertices moved by `transform`.
  void append(const TriangleMesh& other, const glm::mat4& transform = glm::mat4(1.0f));
};

// Area-weighted vertex normals from the triangles, for meshes whose file has none.
std::vector<glm::vec3> vertex_normals(const std::vector<glm::vec3>& positions,
                                      const std::vector<std::uint32_t>& indices);

}  // namespace pointgen
