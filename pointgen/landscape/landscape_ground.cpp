#include "pointgen/landscape/landscape_ground.hpp"

#include "pointgen/landscape/landscape_terrain.hpp"
#include "pointgen/placement/height_grid_mesh.hpp"

#include <cmath>

namespace pointgen {

glm::ivec2 LandscapeGround::first_corner(const LandscapeSpec& spec, glm::vec2 eye) const {
  const float step = 2.0f * radius / static_cast<float>(cells);
  // Lattice corners from the area's (-x, -z) corner; the grid does not start before it nor end
  // past the far corner where the area is wider than the grid.
  const glm::vec2 from_corner = eye - radius + 0.5f * spec.size;
  const glm::ivec2 last = glm::max(glm::ivec2(glm::ceil(spec.size / step)) - cells, glm::ivec2(0));
  return glm::clamp(glm::ivec2(glm::floor(from_corner / step)), glm::ivec2(0), last);
}

TriangleMesh LandscapeGround::mesh(const LandscapeSpec& spec, glm::ivec2 first_corner) const {
  const LandscapeTerrain terrain(spec.terrain, spec.seed);
  const float step = 2.0f * radius / static_cast<float>(cells);
  const glm::vec2 half = 0.5f * spec.size;
  return height_grid_mesh(
      glm::ivec2(cells),
      [&](int i, int j) {
        const glm::vec2 p = glm::clamp(-half + step * glm::vec2(first_corner + glm::ivec2(i, j)), -half, half);
        return glm::vec3(p.x, terrain.height(p.x, p.y), p.y);
      },
      spec.terrain.relief, {});
}

}  // namespace pointgen
