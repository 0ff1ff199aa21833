#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace pointgen {

// Instances of one mesh: each a transform, a tint (linear RGB, multiplied with the mesh's
// colours) and a seed (for anything random about it later, such as its sample points).
// Transforms are affine, so a table keeps their top three rows (glm::mat4x3: 48 bytes, where a
// mat4 takes 64) and seeds of 32 bits: 64 bytes an instance, which is what ten million plants
// cost in memory beyond their species' meshes.
struct InstanceTable {
  std::size_t mesh = 0;
  std::vector<glm::mat4x3> transforms;
  std::vector<glm::vec3> tints;
  std::vector<std::uint32_t> seeds;

  std::size_t size() const { return transforms.size(); }
  glm::mat4 transform(std::size_t i) const { return glm::mat4(transforms[i]); }
  // `transform` must be affine (its last row 0 0 0 1); a seed keeps its low 32 bits.
  void add(const glm::mat4& transform, const glm::vec3& tint, std::uint64_t seed) {
    transforms.emplace_back(transform);
    tints.push_back(tint);
    seeds.push_back(static_cast<std::uint32_t>(seed));
  }
  // Gives back the room that growing by add() left unfilled (up to half of a table).
  void shrink_to_fit() {
    transforms.shrink_to_fit();
    tints.shrink_to_fit();
    seeds.shrink_to_fit();
  }
};

// The scale of an instance's transform (the cube root of its volume change).
inline float uniform_scale(const glm::mat4& transform) { return std::cbrt(std::abs(glm::determinant(glm::mat3(transform)))); }

}  // namespace pointgen
