#pragma once
#include "pointgen/instance_table.hpp"
#include "pointgen/placement/terrain.hpp"
#include "pointgen/plants/plant_species.hpp"

#include <memory>
#include <string>
#include <vector>

namespace pointgen {

struct PlantRequest {
  PlantSpecies species;
  int count = 0;
  int variants = 2;  // meshes per species, each grown from its own seed
  // A species of the user's: this mesh (one variant) in placement layer `layer` instead of grown
  // ones; `species` then gives only its name.
  std::shared_ptr<const TriangleMesh> mesh;
  int layer = 0;
  glm::vec2 scale{0.75f, 1.25f};  // each plant's size factor, uniform between the two
  // The most a plant's colour differs from its mesh's, per channel: each channel of a plant's
  // tint is uniform in [1 - tint, 1 + tint]. 0 keeps the mesh's colours.
  float tint = 0.12f;
};

// A landscape: a terrain over an area and plants on it, placed by Poisson-disk sampling in three
// layers (trees, bushes, ground cover; each layer keeps its own minimum distance) and given to
// species by clustered density maps, so each species grows in groves and patches.
struct EcosystemSpec {
  std::uint64_t seed = 1;
  TerrainSpec terrain;  // its centre and size are the ecosystem's area
  std::vector<PlantRequest> plants;
  std::vector<glm::vec3> clearings;  // (x, z, radius): meadows where no trees or bushes grow
};

struct Ecosystem {
  Terrain terrain;
  std::vector<TriangleMesh> meshes;  // the terrain first, then every species variant
  std::vector<std::string> mesh_names;
  std::vector<InstanceTable> tables;  // one per mesh; the terrain's has one instance
  std::vector<float> layer_radius;    // the minimum distance kept in each layer (trees, bushes, ground)
};

// Throws std::invalid_argument when the clearings leave no room for the plants asked for.
Ecosystem grow_ecosystem(const EcosystemSpec& spec);

// Memory the ecosystem will take in this process, in bytes, known before growing it.
std::size_t estimated_bytes(const EcosystemSpec& spec);

// The placement layer of a plant kind: 0 trees, 1 bushes, 2 ground cover.
int placement_layer(PlantKind kind);
// A request's layer: its mesh's, or its species kind's.
int placement_layer(const PlantRequest& request);

}  // namespace pointgen
