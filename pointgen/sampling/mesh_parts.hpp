#pragma once
#include "pointgen/triangle_mesh.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace pointgen {

// A piece of a point mesh that the sampler can count, hide and draw on its own: a near tree's
// back leaves are hidden by its front leaves only when they are counted apart
// (docs/point_density.md, "Parts").
struct MeshPart {
  std::uint32_t first = 0;    // where its list starts in the mesh's sample list
  std::uint32_t samples = 0;  // length of its list
  float area = 0.0f;          // its share of the mesh's surface, square metres
  glm::vec3 center{0.0f};     // of its samples' bounds, in the mesh's frame
  glm::vec3 half_size{0.0f};
  float radius = 0.0f;
  glm::mat3 normal_moments{0.0f};  // of its samples (point_count.hpp)
};

// The mesh's samples (positions and unit normals) split into the cells of a grid of `cells`³ over
// their bounds. The parts' lists follow the whole list in the mesh's sample list: `order` gives,
// for each place after the whole list, the index of the sample in the whole list that goes there. A part's list keeps the
// whole list's order, so each of its prefixes is a uniform sample of its piece, and an instance
// drawn by parts shows the same points it would show whole (the prefix of the whole list that
// falls in each part). Empty cells have no part.
struct MeshSplit {
  std::vector<MeshPart> parts;
  std::vector<std::uint32_t> order;
};
MeshSplit split_into_parts(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals, float area, int cells = 4);

// A piece of a mesh drawn as polygons that the sampler can skip where nearer objects hide it
// (docs/point_density.md, "Polygon parts"): a range of the reordered index list, and the bounds
// of its triangles.
struct PolygonPart {
  std::uint32_t first_index = 0;
  std::uint32_t index_count = 0;
  glm::vec3 center{0.0f};
  glm::vec3 half_size{0.0f};
};

// The mesh's triangles grouped by the cell of a grid of `cells`³ over its bounds that holds
// each one's centroid: the index list in that order, and a part per non-empty cell (at most 64 with
// the 4³ cells of a point mesh's parts).
struct TriangleSplit {
  std::vector<std::uint32_t> indices;
  std::vector<PolygonPart> parts;
};
TriangleSplit split_triangles(const TriangleMesh& mesh, int cells = 4);

}  // namespace pointgen
