#pragma once
#include "pointgen/landscape/landscape_spec.hpp"
#include "pointgen/sampling/mesh_parts.hpp"
#include "pointgen/triangle_mesh.hpp"

#include <array>
#include <compare>
#include <map>
#include <set>
#include <vector>

namespace pointgen {

// A chunk of a landscape's ground quadtree: level 0 is one square over the whole area, each level
// below halves the side; (x, z) count chunks of its level from the area's (-x, -z) corner.
struct GroundChunkKey {
  int level = 0;
  int x = 0, z = 0;
  auto operator<=>(const GroundChunkKey&) const = default;
};

// A landscape's ground, from near to the horizon, as chunks of a quadtree (a chunked level of
// detail): each chunk a grid of `cells` × `cells` squares, split in four while the eye is within
// `split_distance` of its sides, down to squares of `step` metres, so that squares far away are
// as large to the eye as near ones. Where a chunk meets a larger one, its edge's vertices lie on
// the larger one's edge, so that no crack opens between them. Heights, normals and colours follow
// from the position alone.
class GroundChunks {
 public:
  struct Settings {
    int cells = 16;
    float step = 2.0f;  // metres: the finest squares' side
    float split_distance = 2.0f;
  };
  GroundChunks(LandscapeSpec spec, Settings settings);

  // The chunks for an eye, in key order: the same for the same eye, whatever came before.
  std::vector<GroundChunkKey> chosen(const glm::vec3& eye) const;
  // The chunks' meshes one after the other, in their order, and each one's index range and bounds;
  // a chunk once made is kept while chosen and made again when chosen after it was not.
  struct Chunked {
    TriangleMesh mesh;
    std::vector<PolygonPart> chunks;
  };
  Chunked mesh(const std::vector<GroundChunkKey>& chunks);

  float side(int level) const;  // metres

 private:
  // A chunk and the levels of the larger chunks its edges meet (west, east, south, north; -1:
  // none), which its mesh depends on.
  struct Placed {
    GroundChunkKey key;
    std::array<int, 4> coarser;
    auto operator<=>(const Placed&) const = default;
  };
  std::array<int, 4> coarser_neighbours(const GroundChunkKey& key, const std::set<GroundChunkKey>& chosen) const;
  TriangleMesh chunk_mesh(const Placed& chunk) const;

  LandscapeSpec spec_;
  Settings settings_;
  int finest_level_ = 0;
  std::map<Placed, TriangleMesh> kept_;
};

}  // namespace pointgen
