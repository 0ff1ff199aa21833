#include "pointgen/sampling/mesh_parts.hpp"

#include "pointgen/sampling/point_count.hpp"
#include "pointgen/triangle_mesh.hpp"

#include <algorithm>

namespace pointgen {

namespace {

// The cell of a grid of `cells`³ over `bounds` that holds `p` (clamped into the grid).
int cell_of(const Bounds& bounds, int cells, const glm::vec3& p) {
  const glm::vec3 cell_size = glm::max(bounds.max - bounds.min, glm::vec3(1e-6f)) / static_cast<float>(cells);
  const glm::ivec3 c = glm::clamp(glm::ivec3(glm::floor((p - bounds.min) / cell_size)), glm::ivec3(0), glm::ivec3(cells - 1));
  return (c.z * cells + c.y) * cells + c.x;
}

}  // namespace

MeshSplit split_into_parts(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals, float area, int cells) {
  MeshSplit split;
  if (positions.empty() || cells < 1) return split;
  Bounds all;
  for (const glm::vec3& p : positions) all.add(p);
  std::vector<std::vector<std::uint32_t>> members(static_cast<std::size_t>(cells) * cells * cells);
  for (std::size_t i = 0; i < positions.size(); ++i) members[cell_of(all, cells, positions[i])].push_back(static_cast<std::uint32_t>(i));
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

TriangleSplit split_triangles(const TriangleMesh& mesh, int cells) {
  TriangleSplit split;
  const Bounds all = mesh.bounds();
  if (all.empty() || cells < 1) return split;
  std::vector<std::vector<std::uint32_t>> members(static_cast<std::size_t>(cells) * cells * cells);
  for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t) {
    const glm::vec3 centroid = (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
                                mesh.positions[mesh.indices[3 * t + 2]]) / 3.0f;
    members[cell_of(all, cells, centroid)].push_back(t);
  }
  for (const std::vector<std::uint32_t>& triangles : members) {
    if (triangles.empty()) continue;
    PolygonPart part;
    part.first_index = static_cast<std::uint32_t>(split.indices.size());
    Bounds b;
    for (std::uint32_t t : triangles) {
      for (int corner = 0; corner < 3; ++corner) {
        const std::uint32_t index = mesh.indices[3 * t + corner];
        split.indices.push_back(index);
        b.add(mesh.positions[index]);
      }
    }
    part.index_count = static_cast<std::uint32_t>(split.indices.size()) - part.first_index;
    part.center = 0.5f * (b.min + b.max);
    part.half_size = 0.5f * (b.max - b.min);
    split.parts.push_back(part);
  }
  return split;
}

}  // namespace pointgen
