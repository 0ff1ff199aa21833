#pragma once
#include "pointgen/sampling/instance_cells.hpp"
#include "pointgen/sampling/mesh_parts.hpp"
#include "pointgen/sampling/point_count.hpp"
#include "pointgen/sampling/receiver_mask.hpp"
#include "pointgen/table_list.hpp"

#include <vector>

namespace pointgen {

// What the sampler knows of a mesh whose instances may be drawn as points.
struct SampledMesh {
  float area = 0.0f;            // surface area, square metres
  glm::vec3 center{0.0f};       // of its bounds, in the mesh's frame
  float radius = 0.0f;          // of a sphere around `center` holding the mesh
  std::size_t triangles = 0;
  std::size_t samples = 0;      // length of its surface-sample list
  glm::vec3 half_size{0.0f};    // of its bounds box, around `center`
  // Its sample list's positions in the mesh's frame, for the occlusion model (none: it never hides
  // others nor is hidden): the whole list, then its parts' lists.
  std::vector<glm::vec3> sample_positions;
  // Large near instances are counted part by part (none: always whole).
  std::vector<MeshPart> parts;
  glm::mat3 normal_moments{0.0f};  // of its samples (point_count.hpp; zero: facing every way)
  // Its triangles' parts when drawn as polygons, at most 64 (none: always drawn whole).
  std::vector<PolygonPart> polygon_parts;
};

// The view: what to cull against, the eye, and the density.
struct SamplerView {
  // World → clip matrices: an instance is kept when it is inside any of them (the camera's for a
  // frame; a shadow map's views for its pass).
  std::vector<glm::mat4> views{glm::mat4(1.0f)};
  glm::vec3 eye{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};
  // Counts use the view depth, but at least distance × edge_cos (the cosine of the angle from the
  // view axis to the image corner), so casters outside the camera's view get sensible counts.
  float edge_cos = 0.5f;
  PointDensity density;
  // A point costs about 1 / points_per_triangle of a triangle: an instance needing more points
  // than points_per_triangle × its triangles is cheaper as polygons.
  float points_per_triangle = 4.0f;
  // Count only the surface in front (with one view): what the objects and parts before each one
  // leave uncovered (CoverageGrid), a large near object's back behind its own front.
  bool occlusion = true;
  // Below this much of its screen rectangle left uncovered by nearer objects, an object's count
  // falls linearly to none. The frame keeps full counts until 99 % is hidden (holes show); at 1 the
  // count is the expected visible share, which suits the shadow map.
  float full_count_transmittance = 0.01f;
  glm::ivec2 pixels{256, 256};  // the (first) view's image size
  int splat_pixels = 2;          // per side of a point's splat: what a point hides (>= 1)
  // For a shadow map: counts follow the camera, but the map holds no more than k points per texel
  // of a caster's projected surface, so no caster gets more (with one view).
  bool cap_to_pixels = false;
  // For a shadow map's view (with one view): where the camera saw surfaces; casters whose boxes
  // cover none of it are skipped. None: every caster counts.
  const ReceiverMask* receivers = nullptr;
};

// One instance, or one part of it, drawn as points: `count` samples of its mesh's list from
// `first` (0 for the whole list's prefix, a part's `first` for the prefix of that part's list).
struct PointDraw {
  std::uint32_t table = 0;
  std::uint32_t instance = 0;
  std::uint32_t count = 0;
  std::uint32_t first = 0;
};

struct SampledFrame {
  std::vector<PointDraw> points;  // an instance counted by parts has one per part
  // Per table, the instances drawn as polygons, and for each the polygon parts of its mesh drawn,
  // a bit each (the others are hidden; all ones for a mesh without parts).
  std::vector<std::vector<std::uint32_t>> polygons;
  std::vector<std::vector<std::uint64_t>> polygon_parts;
  std::size_t point_count = 0;
  std::size_t triangle_count = 0;
};

// For each instance in view: points (as many as the view needs) or polygons, whichever is cheaper.
// In a band around the break-even an instance is drawn both ways, its points thinning out over its
// polygons, so the switch shows no pop while every frame stays a function of its own view alone.
// Instances outside the view are culled, cell by cell first; `cells` are those of `tables`.
SampledFrame sample_view(const SamplerView& view, const TableList& tables,
                         const std::vector<SampledMesh>& meshes, const InstanceCells& cells);
// The same, with the tables' cells made for this one view.
SampledFrame sample_view(const SamplerView& view, const TableList& tables,
                         const std::vector<SampledMesh>& meshes);

}  // namespace pointgen
