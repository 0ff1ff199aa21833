#pragma once
#include "app/scene/ecosystem_fields.hpp"
#include "pointgen/landscape/landscape_spec.hpp"

#include <vector>

// The reader for a scene file's landscape: plants made from (seed, cell, site) instead of stored.
namespace ecoview {

struct LandscapeObject {
  pointgen::LandscapeSpec spec;
  std::vector<std::vector<pointgen::TriangleMesh>> meshes;  // per layer, per species
  float radius = 500.0f;     // metres around the camera whose cells are made at load
  int ground_cells = 256;    // the ground's grid over that square, along each side
};

// {"seed", "size": [x, z], "radius", "ground_cells", "terrain": {...}, "species": [...],
//  "layers": [{"name", "cell_size", "density", "species": [entry, ...]}, ...]}; each entry
// {"species": name or {...}} or, for the user's mesh, {"file"}, with "weight", "altitude":
// [lowest, highest], "slope_max_deg", "grove", "grove_size", "scale": [min, max].
LandscapeObject read_landscape(const JsonField& field, std::uint64_t scene_seed, const LoadMesh& load_mesh);

}  // namespace ecoview
