#include "pointgen/triangle_mesh.hpp"

#include <algorithm>
#include <set>

namespace pointgen {

Bounds TriangleMesh::bounds() const {
  Bounds b;
  for (const glm::vec3& p : positions) b.add(p);
  return b;
}

void TriangleMesh::append(const TriangleMesh& other, const glm::mat4& transform) {
  const auto base = static_cast<std::uint32_t>(positions.size());
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(transform)));
  for (std::size_t i = 0; i < other.positions.size(); ++i) {
    positions.push_back(glm::vec3(transform * glm::vec4(other.positions[i], 1.0f)));
    normals.push_back(glm::normalize(normal_matrix * other.normals[i]));
    colors.push_back(other.colors[i]);
  }
  for (std::uint32_t index : other.indices) indices.push_back(base + index);
  if (materials.empty() && other.materials.empty()) return;
  if (materials.empty()) {
    materials.push_back({});
    texcoords.assign(base, glm::vec2(0.0f));
    alphas.assign(base, 1.0f);
    vertex_materials.assign(base, 0u);
  }
  if (other.materials.empty()) {
    texcoords.resize(positions.size(), glm::vec2(0.0f));
    alphas.resize(positions.size(), 1.0f);
    vertex_materials.resize(positions.size(), 0u);
    return;
  }
  const auto shift = static_cast<std::uint32_t>(materials.size() - 1);  // both meshes' material 0 is the plain one
  materials.insert(materials.end(), other.materials.begin() + 1, other.materials.end());
  texcoords.insert(texcoords.end(), other.texcoords.begin(), other.texcoords.end());
  alphas.insert(alphas.end(), other.alphas.begin(), other.alphas.end());
  for (std::uint32_t m : other.vertex_materials) vertex_materials.push_back(m == 0 ? 0 : m + shift);
}

std::optional<glm::vec4> TriangleMesh::kept_texel(std::size_t first, float u, float v) const {
  if (materials.empty()) return glm::vec4(1.0f);
  const std::uint32_t a = indices[first], b = indices[first + 1], c = indices[first + 2];
  const float w = 1.0f - u - v;
  const SurfaceMaterial& material = materials[vertex_materials[a]];
  const glm::vec4 texel = material.texel(w * texcoords[a] + u * texcoords[b] + v * texcoords[c]);
  if (!material.masked()) return texel;
  // Interpolated only where the vertices' alphas differ: the common scale exactly elsewhere.
  const float scale = alphas[a] == alphas[b] && alphas[a] == alphas[c]
                          ? material.keep_scale(alphas[a])
                          : w * material.keep_scale(alphas[a]) + u * material.keep_scale(alphas[b]) + v * material.keep_scale(alphas[c]);
  if (texel.a * scale < 1.0f) return std::nullopt;
  return texel;
}

bool TriangleMesh::masked() const {
  return std::any_of(materials.begin(), materials.end(), [](const SurfaceMaterial& m) { return m.masked(); });
}

std::size_t TriangleMesh::texture_bytes() const {
  std::set<const SurfaceTexture*> textures;
  for (const SurfaceMaterial& material : materials) {
    if (material.texture) textures.insert(material.texture.get());
  }
  std::size_t bytes = 0;
  for (const SurfaceTexture* texture : textures) bytes += texture->bytes();
  return bytes;
}

std::vector<glm::vec3> vertex_normals(const std::vector<glm::vec3>& positions,
                                      const std::vector<std::uint32_t>& indices) {
  std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::vec3& a = positions[indices[t]];
    const glm::vec3& b = positions[indices[t + 1]];
    const glm::vec3& c = positions[indices[t + 2]];
    const glm::vec3 weighted = glm::cross(b - a, c - a);  // length = twice the area
    for (int k = 0; k < 3; ++k) normals[indices[t + k]] += weighted;
  }
  for (glm::vec3& n : normals) {
    const float length = glm::length(n);
    n = length > 0.0f ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
  }
  return normals;
}

}  // namespace pointgen
