#pragma once
#include <glm/glm.hpp>

#include <cstdint>

namespace pointgen {

struct LandscapeTerrainSpec {
  float relief = 300.0f;    // metres from the lowest to the highest hill, about; centred on 0
  float feature = 4000.0f;  // horizontal size of the largest hills, metres
  int octaves = 6;          // each half the size of the one before: 125 m bumps at the defaults
  float valley_depth = 150.0f;
  float valley_width = 5000.0f;         // from the valley's floor to where its sides meet the hills
  float valley_meander = 8000.0f;       // how far the floor wanders from z = 0 ...
  float valley_wavelength = 20000.0f;   // ... over this length along x
};

// Ground over an unbounded plane whose height at (x, z) follows from (seed, x, z) alone: fractal
// value noise for hills, less a broad valley whose floor meanders along x. No table behind it, so
// a 100 km landscape costs nothing until asked, and every thread computes the same floats.
class LandscapeTerrain {
 public:
  LandscapeTerrain(const LandscapeTerrainSpec& spec, std::uint32_t seed);

  float height(float x, float z) const;
  // Up, from the height's differences over `step` metres either side.
  glm::vec3 normal(float x, float z, float step = 1.0f) const;

 private:
  float valley(float x, float z) const;

  LandscapeTerrainSpec spec_;
  std::uint32_t hill_seed_, valley_seed_;
};

}  // namespace pointgen
