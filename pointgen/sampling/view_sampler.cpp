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
// an instance is drawn both as points and as polygons: its polygons whole, its points thinning out
// over them, from its full count at the bottom of the band to none at the top.
constexpr float band_low = 0.8f, band_high = 1.25f;
// An instance certainly drawn as points whose screen rectangle spans more pixels than this is
// counted by parts.
constexpr float pixels_to_split = 1024.0f;

using Frustum = std::array<glm::vec4, 6>;

// The six frustum planes of a view-projection matrix (Gribb-Hartmann), inside where dot >= 0.
Frustum frustum_planes(const glm::mat4& m) {
  const glm::vec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]), r1(m[0][1], m[1][1], m[2][1], m[3][1]),
      r2(m[0][2], m[1][2], m[2][2], m[3][2]), r3(m[0][3], m[1][3], m[2][3], m[3][3]);
  Frustum planes = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2};
  for (glm::vec4& p : planes) p /= glm::length(glm::vec3(p));
  return planes;
}

// What is counted, hidden and drawn as one: an instance inside one of the views, or a part of it.
struct Candidate {
  std::uint32_t table = 0, instance = 0;
  const MeshPart* part = nullptr;  // none: the whole instance
  glm::vec3 center{0.0f};
  float radius = 0.0f;
  float area = 0.0f;   // square metres
  float order = 0.0f;  // depth in the first view: sorted front to back
};

bool inside_any(const std::vector<Frustum>& frusta, const glm::vec3& center, float radius) {
  return std::any_of(frusta.begin(), frusta.end(), [&](const Frustum& planes) {
    return std::all_of(planes.begin(), planes.end(), [&](const glm::vec4& p) { return glm::dot(glm::vec3(p), center) + p.w >= -radius; });
  });
}

float uniform_scale(const glm::mat4& transform) { return std::cbrt(std::abs(glm::determinant(glm::mat3(transform)))); }

// The eight corners of a box in a mesh's frame under an instance's transform.
std::array<glm::vec3, 8> box_corners(const glm::vec3& center, const glm::vec3& half_size, const glm::mat4& transform) {
  std::array<glm::vec3, 8> corners;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 sign((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f);
    corners[i] = glm::vec3(transform * glm::vec4(center + sign * half_size, 1.0f));
  }
  return corners;
}

std::array<glm::vec3, 8> box_corners(const Candidate& c, const SampledMesh& mesh, const glm::mat4& transform) {
  return c.part ? box_corners(c.part->center, c.part->half_size, transform) : box_corners(mesh.center, mesh.half_size, transform);
}

float polygon_equivalent(const SamplerView& view, const SampledMesh& mesh) {
  return view.points_per_triangle * static_cast<float>(mesh.triangles);
}

// Points for k per pixel of the candidate's surface, before anything hides it. With the cap, the
// coverage grid is the map's image.
float unoccluded_count(const SamplerView& view, const CoverageGrid* coverage, const Candidate& c, const SampledMesh& mesh,
                       const glm::mat4& transform) {
  // Distances to the centre: the count is right on average over the object (docs/point_density.md).
  const float distance = std::max(glm::distance(view.eye, c.center), std::max(0.5f * c.radius, 1e-3f));
  const float depth = std::max(glm::dot(c.center - view.eye, view.forward), distance * view.edge_cos);
  // How much its surface faces the eye, in the mesh's frame.
  const glm::vec3 to_eye = glm::inverse(glm::mat3(transform)) * (view.eye - c.center);
  const glm::mat3& moments = c.part ? c.part->normal_moments : mesh.normal_moments;
  const float facing_eye = glm::dot(to_eye, to_eye) > 0.0f ? facing(moments, glm::normalize(to_eye)) : 0.5f;
  float needed = points_needed(view.density, c.area, depth, distance, facing_eye);
  if (coverage && view.cap_to_pixels) {
    // Towards the light, surface is taken as facing every way: half its area projects.
    const float ndc_to_pixels = 0.25f * static_cast<float>(view.pixels.x) * static_cast<float>(view.pixels.y);
    needed = std::min(needed, view.density.k * 0.5f * c.area * coverage->ndc_area_per_square_metre(c.center) * ndc_to_pixels);
  }
  return needed;
}

// Whether an instance is counted by parts: when it is certainly drawn as points (whatever hides
// it, it stays below the band) and its screen rectangle is large, so that its front can hide its back.
bool counted_by_parts(const SamplerView& view, const CoverageGrid& coverage, const SampledMesh& mesh, const glm::mat4& transform,
                      const Candidate& whole) {
  if (mesh.parts.empty() || mesh.sample_positions.empty()) return false;
  // The size first: most instances are small, and their counts are taken once, in sample_view.
  const std::optional<CoverageGrid::Rect> rect = coverage.project(box_corners(mesh.center, mesh.half_size, transform));
  if (!rect || !(coverage.cells_in(*rect) > pixels_to_split)) return false;
  const float needed = unoccluded_count(view, &coverage, whole, mesh, transform);
  return needed < std::min(band_low * polygon_equivalent(view, mesh), static_cast<float>(mesh.samples));
}

// The instances in view, large near ones by their parts in view, sorted front to back. `coverage`
// (when occlusion is on) decides which instances are large.
std::vector<Candidate> candidates_in_view(const SamplerView& view, const std::vector<InstanceTable>& tables,
                                          const std::vector<SampledMesh>& meshes, const CoverageGrid* coverage) {
  std::vector<Frustum> frusta;
  for (const glm::mat4& m : view.views) frusta.push_back(frustum_planes(m));
  std::vector<Candidate> visible;
  for (std::size_t t = 0; t < tables.size(); ++t) {
    const SampledMesh& mesh = meshes[tables[t].mesh];
    for (std::size_t i = 0; i < tables[t].size(); ++i) {
      const glm::mat4& m = tables[t].transforms[i];
      const float scale = uniform_scale(m);
      const Candidate whole{static_cast<std::uint32_t>(t), static_cast<std::uint32_t>(i), nullptr,
                            glm::vec3(m * glm::vec4(mesh.center, 1.0f)), mesh.radius * scale, mesh.area * scale * scale};
      if (!inside_any(frusta, whole.center, whole.radius)) continue;
      if (!coverage || !counted_by_parts(view, *coverage, mesh, m, whole)) {
        visible.push_back(whole);
        continue;
      }
      for (const MeshPart& part : mesh.parts) {
        const Candidate c{whole.table, whole.instance, &part, glm::vec3(m * glm::vec4(part.center, 1.0f)), part.radius * scale,
                          part.area * scale * scale};
        if (inside_any(frusta, c.center, c.radius)) visible.push_back(c);
      }
    }
  }
  for (Candidate& c : visible) {
    const glm::vec4 clip = view.views.front() * glm::vec4(c.center, 1.0f);
    c.order = clip.w > 0.0f ? clip.z / clip.w : -INFINITY;  // centres behind the eye first
  }
  std::sort(visible.begin(), visible.end(), [](const Candidate& a, const Candidate& b) {
    return std::tie(a.order, a.table, a.instance, a.part) < std::tie(b.order, b.table, b.instance, b.part);
  });
  return visible;
}

// The share of its points an object keeps when objects in front hide `transmittance` of its screen
// rectangle on average. Its points are a prefix of a list spread over all of it, so they cannot
// follow which part is hidden: it keeps its full count until nearly all of its rectangle is hidden
// and only then fades out.
float visible_share(float transmittance, float full_count_transmittance) {
  return std::min(1.0f, transmittance / full_count_transmittance);
}

// Covers the splats of the first `drawn` of an object's samples from `first` in its mesh's list,
// but of no more than one per pixel of its rectangle: more add no coverage.
void cover(CoverageGrid& coverage, const SampledMesh& mesh, std::uint32_t first, const glm::mat4& transform,
           const CoverageGrid::Rect& rect, std::size_t drawn) {
  const auto enough = static_cast<std::size_t>(coverage.cells_in(rect)) + 1;
  const std::span<const glm::vec3> list = std::span(mesh.sample_positions).subspan(std::min<std::size_t>(first, mesh.sample_positions.size()));
  coverage.cover(list.first(std::min({drawn, enough, list.size()})), transform);
}

// The candidate's threshold in [0, 1) for rounding its count: fixed per instance and part.
float rounding(const InstanceTable& table, const Candidate& c, const SampledMesh& mesh) {
  const std::uint64_t seed = table.seeds.size() > c.instance ? table.seeds[c.instance] : c.instance;
  return Random(c.part ? derive_seed(seed, static_cast<std::uint64_t>(c.part - mesh.parts.data()) + 1) : seed).uniform();
}

}  // namespace

SampledFrame sample_view(const SamplerView& view, const std::vector<InstanceTable>& tables,
                         const std::vector<SampledMesh>& meshes) {
  SampledFrame frame;
  frame.polygons.resize(tables.size());
  // Occlusion and the cap need one image; several views (cube maps) count every instance whole.
  std::optional<CoverageGrid> coverage;
  if ((view.occlusion || view.cap_to_pixels) && view.views.size() == 1) {
    coverage.emplace(view.views.front(), view.pixels, view.splat_pixels);
  }
  const CoverageGrid* occlusion = coverage && view.occlusion ? &*coverage : nullptr;
  for (const Candidate& c : candidates_in_view(view, tables, meshes, occlusion)) {
    const SampledMesh& mesh = meshes[tables[c.table].mesh];
    const glm::mat4& transform = tables[c.table].transforms[c.instance];
    float needed = unoccluded_count(view, coverage ? &*coverage : nullptr, c, mesh, transform);
    // Only point meshes hide others: ground and buildings are large and far from their bounds.
    std::optional<CoverageGrid::Rect> rect;
    if (occlusion && !mesh.sample_positions.empty()) rect = occlusion->project(box_corners(c, mesh, transform));
    if (rect) needed *= visible_share(coverage->transmittance(*rect), view.full_count_transmittance);
    const std::uint32_t first = c.part ? c.part->first : 0;
    const std::size_t samples = c.part ? c.part->samples : mesh.samples;
    const float ratio = needed / polygon_equivalent(view, mesh);
    const bool as_polygons = !c.part && (ratio > band_low || needed > static_cast<float>(samples));
    const bool as_points = (c.part || ratio < band_high) && samples > 0;
    const float drawn = as_polygons ? needed * std::clamp((band_high - ratio) / (band_high - band_low), 0.0f, 1.0f) : needed;
    // Rounded up or down at the candidate's own fixed threshold: unbiased over many small
    // instances, and steady from frame to frame.
    const auto count = static_cast<std::uint32_t>(std::min(std::floor(drawn + rounding(tables[c.table], c, mesh)),
                                                           static_cast<float>(samples)));
    if (as_points && count > 0) {
      frame.points.push_back({c.table, c.instance, count, first});
      frame.point_count += count;
    }
    if (as_polygons) {
      frame.polygons[c.table].push_back(c.instance);
      frame.triangle_count += mesh.triangles;
    }
    if (rect) cover(*coverage, mesh, first, transform, *rect, as_polygons ? mesh.samples : (as_points ? count : 0));
  }
  return frame;
}

}  // namespace pointgen
