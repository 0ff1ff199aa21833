#include "pointgen/sampling/mesh_parts.hpp"

#include "pointgen/sampling/point_count.hpp"
#include "pointgen/triangle_mesh.hpp"

#include <algorithm>

namespace pointgen {

MeshSplit split_into_parts(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals, float area, int cells) {
  MeshSplit split;
  if (positions.empty() || cells < 1) return split;
  Bounds all;
  for (const glm::vec3& p : positions) all.add(p);
  const glm::vec3 cell_size = glm::max(all.max - all.min, glm::vec3(1e-6f)) / static_cast<float>(cells);
  const auto cell_of = [&](const glm::vec3& p) {
    const glm::ivec3 c = glm::clamp(glm::ivec3(glm::floor((p - all.min) / cell_size)), glm::ivec3(0), glm::ivec3(cells - 1));
    return (c.z * cells + c.y) * cells + c.x;
  };
  std::vector<std::vector<std::uint32_t>> members(static_cast<std::size_t>(cells) * cells * cells);
  for (std::size_t i = 0; i < positions.size(); ++i) members[cell_of(positions[i])].push_back(static_cast<std::uint32_t>(i));
  const auto total = static_cast<float>(positions.size());
  for (const std::vector<std::uint32_t>& list : members) {
    if (list.empty()) continue;
    Bounds b;
    std::vector<glm::vec3> part_normals;
    for (std::uint32_t i : list) {
      b.add(positions[i]);
      part_normals.push_back(normals[i]);
    }
    MeshPart part;
    part.first = static_cast<std::uint32_t>(positions.size() + split.order.size());
    part.samples = static_cast<std::uint32_t>(list.size());
    part.area = area * static_cast<float>(list.size()) / total;
    part.center = 0.5f * (b.min + b.max);
    part.half_size = 0.5f * (b.max - b.min);
    part.radius = glm::length(part.half_size);
    part.normal_moments = normal_moments(part_normals);
    split.parts.push_back(part);
    split.order.insert(split.order.end(), list.begin(), list.end());
  }
  return split;
}

}  // namespace pointgen
