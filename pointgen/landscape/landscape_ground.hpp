#pragma once
#include "pointgen/landscape/landscape_spec.hpp"
#include "pointgen/triangle_mesh.hpp"

namespace pointgen {

// A landscape's ground around an eye at (x, z): a grid of cells × cells squares of side
// 2 · radius / cells whose corners stand on a lattice fixed in the world, so that a moving eye
// moves the grid by whole squares and the ground never swims; clamped to the landscape's area.
struct LandscapeGround {
  float radius = 500.0f;
  int cells = 256;

  // The lattice corner the grid starts at for this eye: the grid changes only when it does.
  glm::ivec2 first_corner(const LandscapeSpec& spec, glm::vec2 eye) const;
  // The same number of vertices and triangles, in the same order, for any eye.
  TriangleMesh mesh(const LandscapeSpec& spec, glm::ivec2 first_corner) const;
};

}  // namespace pointgen
