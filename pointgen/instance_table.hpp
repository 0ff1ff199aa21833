#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace pointgen {

// Instances of one mesh: each a transform, a tint (linear RGB, multiplied with the mesh's
// colours) and a seed (for anything random about it later, such as its sample points).
struct InstanceTable {
  std::size_t mesh = 0;
  std::vector<glm::mat4> transforms;
  std::vector<glm::vec3> tints;
  std::vector<std::uint64_t> seeds;

  std::size_t size() const { return transforms.size(); }
  void add(const glm::mat4& transform, const glm::vec3& tint, std::uint64_t seed) {
    transforms.push_back(transform);
    tints.push_back(tint);
    seeds.push_back(seed);
  }
};

// The scale of an instance's transform (the cube root of its volume change).
inline float uniform_scale(const glm::mat4& transform) { return std::cbrt(std::abs(glm::determinant(glm::mat3(transform)))); }

}  // namespace pointgen
