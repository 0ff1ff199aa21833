#include "pointgen/sampling/frustum_culling.hpp"

#include "pointgen/sampling/view_sampler.hpp"

#include <algorithm>

namespace pointgen {

// The six planes of each view-projection matrix (Gribb-Hartmann), normalized.
ViewFrusta::ViewFrusta(const std::vector<glm::mat4>& views) {
  for (const glm::mat4& m : views) {
    const glm::vec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]), r1(m[0][1], m[1][1], m[2][1], m[3][1]),
        r2(m[0][2], m[1][2], m[2][2], m[3][2]), r3(m[0][3], m[1][3], m[2][3], m[3][3]);
    std::array<glm::vec4, 6> planes = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2};
    for (glm::vec4& p : planes) p /= glm::length(glm::vec3(p));
    planes_.push_back(planes);
  }
}

bool ViewFrusta::hold(const glm::vec3& center, float radius) const {
  return std::any_of(planes_.begin(), planes_.end(), [&](const std::array<glm::vec4, 6>& planes) {
    return std::all_of(planes.begin(), planes.end(), [&](const glm::vec4& p) { return glm::dot(glm::vec3(p), center) + p.w >= -radius; });
  });
}

std::vector<std::uint32_t> instances_in_view(const ViewFrusta& frusta, const std::vector<InstanceCell>& cells,
                                             const InstanceTable& table, const SampledMesh& mesh) {
  std::vector<std::uint32_t> seen;
  for (const InstanceCell& cell : cells) {
    if (!frusta.hold(0.5f * (cell.min + cell.max), 0.5f * glm::length(cell.max - cell.min))) continue;
    for (std::uint32_t i : cell.members) {
      const glm::mat4 m = table.transform(i);
      if (frusta.hold(glm::vec3(m * glm::vec4(mesh.center, 1.0f)), mesh.radius * uniform_scale(m))) seen.push_back(i);
    }
  }
  std::sort(seen.begin(), seen.end());  // drawn in the table's order, as without culling
  return seen;
}

}  // namespace pointgen
