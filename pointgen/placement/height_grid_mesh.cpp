#include "pointgen/placement/height_grid_mesh.hpp"

#include <algorithm>

namespace pointgen {

TriangleMesh height_grid_mesh(glm::ivec2 cells, const std::function<glm::vec3(int i, int j)>& vertex, float relief,
                              const GroundColors& colors) {
  TriangleMesh mesh;
  for (int j = 0; j <= cells.y; ++j) {
    for (int i = 0; i <= cells.x; ++i) mesh.positions.push_back(vertex(i, j));
  }
  const auto row = static_cast<std::uint32_t>(cells.x + 1);
  for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(cells.y); ++j) {
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(cells.x); ++i) {
      const std::uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, d, b, a, c, d});
    }
  }
  mesh.normals = vertex_normals(mesh.positions, mesh.indices);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) mesh.colors.push_back(ground_color(colors, mesh.positions[v].y, relief, mesh.normals[v]));
  return mesh;
}

glm::vec3 ground_color(const GroundColors& colors, float height, float relief, const glm::vec3& normal) {
  const float above = relief > 0.0f ? height / relief + 0.5f : 0.0f;
  const float steep = 1.0f - normal.y;
  return glm::mix(colors.low, colors.high, std::clamp(0.7f * above + 3.0f * steep, 0.0f, 1.0f));
}

}  // namespace pointgen
