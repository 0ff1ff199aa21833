#include "pointgen/sampling/view_sampler.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace pointgen {
namespace {

// The band around break-even, as ratios of needed points to the polygon-equivalent count, in which
// an instance is drawn both as points and as polygons.
constexpr float band_low = 0.8f, band_high = 1.25f;

// The six frustum planes of a view-projection matrix (Gribb-Hartmann), inside where dot >= 0.
std::array<glm::vec4, 6> frustum_planes(const glm::mat4& m) {
  const glm::vec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]), r1(m[0][1], m[1][1], m[2][1], m[3][1]),
      r2(m[0][2], m[1][2], m[2][2], m[3][2]), r3(m[0][3], m[1][3], m[2][3], m[3][3]);
  std::array<glm::vec4, 6> planes = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2};
  for (glm::vec4& p : planes) p /= glm::length(glm::vec3(p));
  return planes;
}

}  // namespace

SampledFrame sample_view(const SamplerView& view, const std::vector<InstanceTable>& tables,
                         const std::vector<SampledMesh>& meshes) {
  std::vector<std::array<glm::vec4, 6>> frusta;
  for (const glm::mat4& m : view.views) frusta.push_back(frustum_planes(m));
  SampledFrame frame;
  frame.polygons.resize(tables.size());
  for (std::size_t t = 0; t < tables.size(); ++t) {
    const InstanceTable& table = tables[t];
    const SampledMesh& mesh = meshes[table.mesh];
    for (std::size_t i = 0; i < table.size(); ++i) {
      const glm::mat4& m = table.transforms[i];
      const glm::vec3 center(m * glm::vec4(mesh.center, 1.0f));
      const float scale = std::cbrt(std::abs(glm::determinant(glm::mat3(m))));
      const float radius = mesh.radius * scale;
      const bool visible = std::any_of(frusta.begin(), frusta.end(), [&](const std::array<glm::vec4, 6>& planes) {
        return std::all_of(planes.begin(), planes.end(), [&](const glm::vec4& p) { return glm::dot(glm::vec3(p), center) + p.w >= -radius; });
      });
      if (!visible) continue;
      // Distances to the centre: the count is right on average over the object (docs/point_density.md).
      const float distance = std::max(glm::distance(view.eye, center), std::max(0.5f * radius, 1e-3f));
      const float depth = std::max(glm::dot(center - view.eye, view.forward), distance * view.edge_cos);
      const float needed = points_needed(view.density, mesh.area * scale * scale, depth, distance);
      const float polygon_equivalent = view.points_per_triangle * static_cast<float>(mesh.triangles);
      const float ratio = needed / polygon_equivalent;
      const bool as_polygons = ratio > band_low || needed > static_cast<float>(mesh.samples);
      const bool as_points = ratio < band_high && mesh.samples > 0;
      if (as_points) {
        const auto count = static_cast<std::uint32_t>(std::min(std::ceil(needed), static_cast<float>(mesh.samples)));
        frame.points.push_back({static_cast<std::uint32_t>(t), static_cast<std::uint32_t>(i), count});
        frame.point_count += count;
      }
      if (as_polygons) {
        frame.polygons[t].push_back(static_cast<std::uint32_t>(i));
        frame.triangle_count += mesh.triangles;
      }
    }
  }
  return frame;
}

}  // namespace pointgen
