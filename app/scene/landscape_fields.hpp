#pragma once
#include "app/scene/ecosystem_fields.hpp"
#include "pointgen/landscape/ground_chunks.hpp"
#include "pointgen/landscape/landscape_spec.hpp"

#include <vector>

// The reader for a scene file's landscape: plants made from (seed, cell, site) instead of stored.
namespace ecoview {

struct LandscapeObject {
  pointgen::LandscapeSpec spec;
  std::vector<std::vector<pointgen::TriangleMesh>> meshes;  // per layer, per species
  float radius = 500.0f;     // a layer's reach unless it has its own
  std::vector<float> reach;  // per layer: metres from the camera within which its cells are made
  pointgen::GroundChunks::Settings ground;  // "ground_cells" a chunk's side, "ground_step" metres
};

// {"seed", "size": [x, z], "radius", "ground_cells", "ground_step", "terrain": {...}, "species": [...],
//  "layers": [{"name", "cell_size", "density", "radius", "species": [entry, ...]}, ...]}: a
// layer's radius (its cells' reach) defaults to the object's; each entry
// {"species": name or {...}} or, for the user's mesh, {"file"}, with "weight", "altitude":
// [lowest, highest], "slope_max_deg", "grove", "grove_size", "scale": [min, max].
LandscapeObject read_landscape(const JsonField& field, std::uint64_t scene_seed, const LoadMesh& load_mesh);

}  // namespace ecoview
