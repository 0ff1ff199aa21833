#pragma once
#include "app/scene/ecosystem_fields.hpp"
#include "pointgen/landscape/landscape_ground.hpp"
#include "pointgen/landscape/landscape_spec.hpp"

#include <vector>

// The reader for a scene file's landscape: plants made from (seed, cell, site) instead of stored.
namespace ecoview {

struct LandscapeObject {
  pointgen::LandscapeSpec spec;
  std::vector<std::vector<pointgen::TriangleMesh>> meshes;  // per layer, per species
  std::vector<float> reach;  // per layer: metres from the camera within which its cells are made
  pointgen::LandscapeGround ground;  // its radius: the object's "radius", its cells "ground_cells"
};

// {"seed", "size": [x, z], "radius", "ground_cells", "terrain": {...}, "species": [...],
//  "layers": [{"name", "cell_size", "density", "radius", "species": [entry, ...]}, ...]}: a
// layer's radius (its cells' reach) defaults to the object's, the ground's; each entry
// {"species": name or {...}} or, for the user's mesh, {"file"}, with "weight", "altitude":
// [lowest, highest], "slope_max_deg", "grove", "grove_size", "scale": [min, max].
LandscapeObject read_landscape(const JsonField& field, std::uint64_t scene_seed, const LoadMesh& load_mesh);

}  // namespace ecoview
