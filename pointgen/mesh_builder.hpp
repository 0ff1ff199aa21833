#pragma once
#include "pointgen/triangle_mesh.hpp"

#include <memory>
#include <vector>

namespace pointgen {

// Builds a mesh from simple parts in an OpenMesh triangle mesh, which computes the vertex
// normals; each part has its own vertices, so normals are smooth within a part and hard between
// parts. Colours are linear RGB per part.
class MeshBuilder {
 public:
  MeshBuilder();
  ~MeshBuilder();
  MeshBuilder(const MeshBuilder&) = delete;
  MeshBuilder& operator=(const MeshBuilder&) = delete;

  // A tapered tube from a to b (radii ra, rb) with `sides` sides; open ends unless capped.
  void tube(const glm::vec3& a, const glm::vec3& b, float ra, float rb, int sides, const glm::vec3& color,
            bool capped = false);
  // A surface of revolution around +Y: profile points (radius, height) from bottom to top,
  // placed by `transform`. A radius of 0 closes the surface at that end.
  void lathe(const std::vector<glm::vec2>& profile, int sides, const glm::vec3& color,
             const glm::mat4& transform = glm::mat4(1.0f));
  // The ellipsoid of the unit sphere placed by `transform`.
  void ellipsoid(const glm::mat4& transform, const glm::vec3& color, int slices = 8, int stacks = 5);
  // The cube [-0.5, 0.5]^3 placed by `transform`, with flat faces.
  void box(const glm::mat4& transform, const glm::vec3& color);
  // A flat leaf: a diamond from `base` along `along` (length), `width` wide across `side`.
  void leaf(const glm::vec3& base, const glm::vec3& along, const glm::vec3& side, float length, float width,
            const glm::vec3& color);
  // A curved strip through `spine` points, `widths` wide across `side` at each point.
  void strip(const std::vector<glm::vec3>& spine, const std::vector<float>& widths, const glm::vec3& side,
             const glm::vec3& color);
  // A triangle or quad with its own (flat) vertices, counter-clockwise seen from its front.
  void polygon(const std::vector<glm::vec3>& corners, const glm::vec3& color);

  TriangleMesh build() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pointgen
