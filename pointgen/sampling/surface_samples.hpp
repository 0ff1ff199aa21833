#pragma once
#include "pointgen/triangle_mesh.hpp"

#include <cstdint>
#include <vector>

namespace pointgen {

// A point on a mesh surface, with the surface's normal and colour there (its texture's colour
// times its vertex colour).
struct SurfaceSample {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec3 color;
};

// `count` points on the surface of `mesh`, spread by area: the i-th is the i-th of a Halton
// sequence shifted by a random offset per seed, its first coordinate a place along the triangles'
// cumulative area table, its second a place across that triangle. Every point is uniform on the
// surface and every prefix of the list is a uniform sample of it, spread more evenly than
// independent draws would be (no triangle far off its share, few gaps), so a renderer can draw the
// first n for any n and change n from frame to frame without the points jumping. Same mesh and
// seed, same list. On a mesh with alpha masks the points lie only where the masks keep the
// surface, spread by kept area; the list may be shorter than `count` where a mask keeps little.
std::vector<SurfaceSample> sample_surface(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed);

// The area of the mesh's surface, square metres: its triangles', less what alpha masks cut away.
float surface_area(const TriangleMesh& mesh);

}  // namespace pointgen
