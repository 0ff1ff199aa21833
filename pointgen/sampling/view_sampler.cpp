#include "pointgen/sampling/view_sampler.hpp"

#include "pointgen/random.hpp"
#include "pointgen/sampling/coverage_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <tuple>

namespace pointgen {
namespace {

// The band around break-even, as ratios of needed points to the polygon-equivalent count, in which
// an instance is drawn both as points and as polygons.
constexpr float band_low = 0.8f, band_high = 1.25f;

using Frustum = std::array<glm::vec4, 6>;

// The six frustum planes of a view-projection matrix (Gribb-Hartmann), inside where dot >= 0.
Frustum frustum_planes(const glm::mat4& m) {
  const glm::vec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]), r1(m[0][1], m[1][1], m[2][1], m[3][1]),
      r2(m[0][2], m[1][2], m[2][2], m[3][2]), r3(m[0][3], m[1][3], m[2][3], m[3][3]);
  Frustum planes = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2};
  for (glm::vec4& p : planes) p /= glm::length(glm::vec3(p));
  return planes;
}

// An instance inside one of the views, with what the count needs of it.
struct Candidate {
  std::uint32_t table = 0, instance = 0;
  glm::vec3 center{0.0f};
  float radius = 0.0f;
  float area = 0.0f;       // square metres
  float order = 0.0f;      // depth in the first view: sorted front to back
};

std::vector<Candidate> visible_instances(const SamplerView& view, const std::vector<InstanceTable>& tables,
                                         const std::vector<SampledMesh>& meshes) {
  std::vector<Frustum> frusta;
  for (const glm::mat4& m : view.views) frusta.push_back(frustum_planes(m));
  std::vector<Candidate> visible;
  for (std::size_t t = 0; t < tables.size(); ++t) {
    const SampledMesh& mesh = meshes[tables[t].mesh];
    for (std::size_t i = 0; i < tables[t].size(); ++i) {
      const glm::mat4& m = tables[t].transforms[i];
      const float scale = std::cbrt(std::abs(glm::determinant(glm::mat3(m))));
      Candidate c{static_cast<std::uint32_t>(t), static_cast<std::uint32_t>(i), glm::vec3(m * glm::vec4(mesh.center, 1.0f)),
                  mesh.radius * scale, mesh.area * scale * scale};
      const bool inside = std::any_of(frusta.begin(), frusta.end(), [&](const Frustum& planes) {
        return std::all_of(planes.begin(), planes.end(), [&](const glm::vec4& p) { return glm::dot(glm::vec3(p), c.center) + p.w >= -c.radius; });
      });
      if (!inside) continue;
      const glm::vec4 clip = view.views.front() * glm::vec4(c.center, 1.0f);
      c.order = clip.w > 0.0f ? clip.z / clip.w : -INFINITY;  // centres behind the eye first
      visible.push_back(c);
    }
  }
  std::sort(visible.begin(), visible.end(), [](const Candidate& a, const Candidate& b) {
    return std::tie(a.order, a.table, a.instance) < std::tie(b.order, b.table, b.instance);
  });
  return visible;
}

// The eight corners of a mesh's bounds box under an instance's transform.
std::array<glm::vec3, 8> box_corners(const SampledMesh& mesh, const glm::mat4& transform) {
  std::array<glm::vec3, 8> corners;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 sign((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f);
    corners[i] = glm::vec3(transform * glm::vec4(mesh.center + sign * mesh.half_size, 1.0f));
  }
  return corners;
}

// The share of its points an object keeps when objects in front hide `transmittance` of its screen
// rectangle on average. Its points are a prefix of a list spread over all of it, so they cannot
// follow which part is hidden: it keeps its full count until nearly all of its rectangle is hidden
// and only then fades out.
float visible_share(float transmittance, float full_count_transmittance) {
  return std::min(1.0f, transmittance / full_count_transmittance);
}

// Covers the cells of the first `drawn` of an object's samples, but of no more than a few per cell
// of its rectangle: more add no coverage.
void cover(CoverageGrid& coverage, const SampledMesh& mesh, const glm::mat4& transform, const CoverageGrid::Rect& rect,
           std::size_t drawn) {
  const auto enough = static_cast<std::size_t>(4.0f * coverage.cells_in(rect)) + 1;
  const std::size_t n = std::min({drawn, enough, mesh.sample_positions.size()});
  coverage.cover(std::span(mesh.sample_positions).first(n), transform);
}

// The instance's threshold in [0, 1) for rounding its count.
float rounding(const InstanceTable& table, std::uint32_t instance) {
  return Random(table.seeds.size() > instance ? table.seeds[instance] : instance).uniform();
}

}  // namespace

SampledFrame sample_view(const SamplerView& view, const std::vector<InstanceTable>& tables,
                         const std::vector<SampledMesh>& meshes) {
  SampledFrame frame;
  frame.polygons.resize(tables.size());
  // Occlusion and the cap need one image; several views (cube maps) count every instance whole.
  std::optional<CoverageGrid> coverage;
  if ((view.occlusion || view.cap_to_pixels) && view.views.size() == 1) {
    const int splat = std::max(view.splat_pixels, 1);
    coverage.emplace(view.views.front(), (view.pixels + splat - 1) / splat);
  }
  const float ndc_to_pixels = 0.25f * static_cast<float>(view.pixels.x) * static_cast<float>(view.pixels.y);
  for (const Candidate& c : visible_instances(view, tables, meshes)) {
    const SampledMesh& mesh = meshes[tables[c.table].mesh];
    // Distances to the centre: the count is right on average over the object (docs/point_density.md).
    const float distance = std::max(glm::distance(view.eye, c.center), std::max(0.5f * c.radius, 1e-3f));
    const float depth = std::max(glm::dot(c.center - view.eye, view.forward), distance * view.edge_cos);
    float needed = points_needed(view.density, c.area, depth, distance);
    if (coverage && view.cap_to_pixels) {
      // Randomly oriented two-sided surface projects to half its area (docs/point_density.md).
      needed = std::min(needed, view.density.k * 0.5f * c.area * coverage->ndc_area_per_square_metre(c.center) * ndc_to_pixels);
    }
    // Only point meshes hide others: ground and buildings are large and far from their bounds.
    const glm::mat4& transform = tables[c.table].transforms[c.instance];
    std::optional<CoverageGrid::Rect> rect;
    if (coverage && view.occlusion && !mesh.sample_positions.empty()) rect = coverage->project(box_corners(mesh, transform));
    if (rect) needed *= visible_share(coverage->transmittance(*rect), view.full_count_transmittance);
    const float polygon_equivalent = view.points_per_triangle * static_cast<float>(mesh.triangles);
    const float ratio = needed / polygon_equivalent;
    const bool as_polygons = ratio > band_low || needed > static_cast<float>(mesh.samples);
    const bool as_points = ratio < band_high && mesh.samples > 0;
    // Rounded up or down at the instance's own fixed threshold: unbiased over many small instances,
    // and steady from frame to frame.
    const auto count = static_cast<std::uint32_t>(std::min(std::floor(needed + rounding(tables[c.table], c.instance)),
                                                           static_cast<float>(mesh.samples)));
    if (as_points && count > 0) {
      frame.points.push_back({c.table, c.instance, count});
      frame.point_count += count;
    }
    if (as_polygons) {
      frame.polygons[c.table].push_back(c.instance);
      frame.triangle_count += mesh.triangles;
    }
    if (rect) cover(*coverage, mesh, transform, *rect, as_polygons ? mesh.samples : (as_points ? count : 0));
  }
  return frame;
}

}  // namespace pointgen
