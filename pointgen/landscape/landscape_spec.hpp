#pragma once
#include "pointgen/landscape/landscape_terrain.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace pointgen {

// Where a species grows within its layer, how often it is picked there, and how its plants vary.
struct LandscapeSpecies {
  std::string name;
  float weight = 1.0f;  // share of its layer's sites, relative to the layer's other species
  glm::vec2 altitude{-1e9f, 1e9f};  // metres, lowest and highest ground it grows on
  float slope_max_deg = 90.0f;      // steepest ground it grows on
  // Groves and clearings: it grows only where its own noise field (fractal value noise of
  // features grove_size metres wide, in [0, 1]) is at least `grove`; 0 grows everywhere.
  float grove = 0.0f;
  float grove_size = 300.0f;
  glm::vec2 scale{0.75f, 1.25f};  // each plant's size factor, uniform between the two
  // Each tint channel uniform in [1 - spread, 1 + spread]: grown species vary their colours so;
  // a user's mesh brings its own colours and wants 0.
  float tint_spread = 0.12f;
  float surface = 1.0f;  // m² of the species' mesh at scale 1, for expected_surface()
  float height = 1.0f;   // metres its mesh stands at scale 1, for far blocks seen from the side
};

// Plants of one height class (trees, bushes, ground cover) made cell by cell: `density` plants per
// m² where every species grows, over square cells of side `cell_size`.
struct LandscapeLayer {
  std::string name;
  float cell_size = 64.0f;
  float density = 0.01f;
  std::vector<LandscapeSpecies> species;

  float total_weight() const;
};

// A landscape with no plant stored: a square area centred on the origin whose ground and plants
// follow from `seed` and these numbers alone.
struct LandscapeSpec {
  static constexpr float max_size = 100000.0f;           // 100 km a side
  static constexpr float max_sites_per_cell = 1 << 20;   // a cell's plants in one vector

  std::uint32_t seed = 1;
  glm::vec2 size{2000.0f};  // metres along x and z
  LandscapeTerrainSpec terrain;
  std::vector<LandscapeLayer> layers;

  // Every field in its valid range; throws std::invalid_argument naming the first that is not
  // (as layers[1].species[0].scale).
  void check() const;
};

}  // namespace pointgen
