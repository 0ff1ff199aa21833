#pragma once
#include "pointgen/triangle_mesh.hpp"

#include <functional>

namespace pointgen {

// The ground's colours: low in valleys, high on tops and steep slopes.
struct GroundColors {
  glm::vec3 low{0.20f, 0.33f, 0.08f};
  glm::vec3 high{0.42f, 0.40f, 0.22f};
};

// The ground's colour at `height` (relative to `relief`, centred on 0) where it faces `normal`.
glm::vec3 ground_color(const GroundColors& colors, float height, float relief, const glm::vec3& normal);

// A height field drawn as a grid of (cells.x + 1) × (cells.y + 1) vertices at vertex(i, j), each
// cell two triangles split along its diagonal from (0, 0) to (1, 1), counter-clockwise seen from
// above (+Y); coloured by height (relative to `relief`, centred on 0) and steepness.
TriangleMesh height_grid_mesh(glm::ivec2 cells, const std::function<glm::vec3(int i, int j)>& vertex, float relief,
                              const GroundColors& colors);

}  // namespace pointgen
