#pragma once
#include "shadow/box.hpp"
#include "shadow/plane.hpp"

#include <array>
#include <span>
#include <vector>

namespace shadow {

// A convex polyhedron held as its faces (planar vertex loops), cut down by planes. Used for the
// focus bodies: the view frustum, the scene box, their intersections with light volumes.
class ConvexBody {
 public:
  using Polygon = std::vector<glm::vec3>;

  static ConvexBody from_box(const Box& box);
  // A hexahedron from 8 corners indexed like Box::corner (bit 0: +x side, bit 1: +y, bit 2: +z),
  // e.g. a view frustum from the corners of its NDC cube.
  static ConvexBody from_corners(const std::array<glm::vec3, 8>& corners);

  // Keeps the part inside the plane (distance <= 0).
  void clip(const Plane& plane);
  void clip(std::span<const Plane> planes);

  // The body with every vertex moved by `transform`: an affine map, or a projective one under
  // which the whole body keeps w > 0 (the PSM's post-perspective space); both keep it convex.
  ConvexBody transformed(const glm::mat4& transform) const;

  bool empty() const { return faces_.empty(); }
  const std::vector<Polygon>& faces() const { return faces_; }
  // The distinct vertices.
  std::vector<glm::vec3> vertices() const;
  // The mean of the distinct vertices: a point inside.
  glm::vec3 centroid() const;
  // The plane of each face, oriented outwards.
  std::vector<Plane> face_planes() const;

 private:
  std::vector<Polygon> faces_;
};

}  // namespace shadow
