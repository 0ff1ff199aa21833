#pragma once
#include "pointgen/surface_texture.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <optional>
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
  // Meshes with textures or alpha masks (glTF materials): per vertex a texture coordinate, the
  // vertex colour's alpha (glTF COLOR_0's, 1 where it has none) and the index of its material;
  // all four empty for meshes of vertex colours alone. Material 0 is always the plain one (vertex
  // colours, opaque), for vertices without a material of their own.
  std::vector<glm::vec2> texcoords;
  std::vector<float> alphas;
  std::vector<std::uint32_t> vertex_materials;
  std::vector<SurfaceMaterial> materials;

  std::size_t triangle_count() const { return indices.size() / 3; }
  // The texel at barycentric (u, v) of the triangle starting at index `first` (white where it has
  // no texture), or nothing where its mask cuts the surface away: where texture alpha × the
  // material's × the vertex colours' interpolated falls short of the cutoff. A triangle has its
  // first vertex's material (glTF primitives share no vertices).
  std::optional<glm::vec4> kept_texel(std::size_t first, float u, float v) const;
  // Whether an alpha mask cuts any of its surface away.
  bool masked() const;
  // Bytes of its materials' texture images, each counted once.
  std::size_t texture_bytes() const;
  Bounds bounds() const;
  // Appends `other`, its vertices moved by `transform`.
  void append(const TriangleMesh& other, const glm::mat4& transform = glm::mat4(1.0f));
};

// Area-weighted vertex normals from the triangles, for meshes whose file has none.
std::vector<glm::vec3> vertex_normals(const std::vector<glm::vec3>& positions,
                                      const std::vector<std::uint32_t>& indices);

}  // namespace pointgen
