#pragma once
#include "pointgen/triangle_mesh.hpp"

#include <cstdint>
#include <vector>

namespace pointgen {

// A point on a mesh surface, with the surface's normal and colour there.
struct SurfaceSample {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec3 color;
};

// `count` points on the surface of `mesh`, each drawn independently: a triangle with probability
// proportional to its area (a cumulative area table), then a uniform point in it. Because the
// draws are independent, every prefix of the list is itself a uniform sample of the surface, so a
// renderer can draw the first n for any n and change n from frame to frame without the points
// jumping. Same mesh and seed, same list.
std::vector<SurfaceSample> sample_surface(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed);

// The total area of the mesh's triangles, square metres.
float surface_area(const TriangleMesh& mesh);

}  // namespace pointgen
