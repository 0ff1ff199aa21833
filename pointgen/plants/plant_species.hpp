#pragma once
#include "pointgen/triangle_mesh.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace pointgen {

enum class PlantKind { broadleaf, conifer, palm, bush, grass, flower, cactus };

// The parameters of a plant species; build_plant turns them and a seed into a mesh. Sizes are
// metres; colours linear RGB.
struct PlantSpecies {
  std::string name;
  PlantKind kind = PlantKind::broadleaf;
  float height = 10.0f;
  float crown = 0.6f;       // crown (or tuft) width relative to height
  float trunk = 0.03f;      // trunk radius relative to height
  int levels = 3;           // branching depth (trees, bushes); tiers (conifers); segments (others)
  int branches = 4;         // children per branch; arms per tier; blades, fronds, petals
  float angle_deg = 40.0f;  // branch angle from its parent
  float leaf_size = 0.25f;
  int leaves = 8;           // leaves per twig
  float droop = 0.0f;       // how much branches and leaves hang (0: none, 1: weeping)
  glm::vec3 bark{0.30f, 0.20f, 0.12f};
  glm::vec3 leaf{0.15f, 0.40f, 0.10f};
  glm::vec3 bloom{0.9f, 0.9f, 0.9f};  // flowers and blossom; unused where bloom_share is 0
  float bloom_share = 0.0f;           // fraction of leaves that are blossom

  // Every field in its valid range; throws std::invalid_argument naming the first that is not.
  void check() const;
};

// The plant's mesh, standing on the origin and growing up +Y. Same species and seed, same mesh.
TriangleMesh build_plant(const PlantSpecies& species, std::uint64_t seed);

// The species that ship with ecoview, all visibly different.
const std::vector<PlantSpecies>& plant_catalogue();
const PlantSpecies* find_species(const std::string& name);

std::string plant_kind_name(PlantKind kind);
// Throws std::invalid_argument listing the kinds when `name` is none of them.
PlantKind parse_plant_kind(const std::string& name);

}  // namespace pointgen
