#include "pointgen/landscape/landscape_terrain.hpp"

#include "pointgen/landscape/hash32.hpp"
#include "pointgen/landscape/value_noise.hpp"

#include <algorithm>

namespace pointgen {
namespace {

constexpr std::uint32_t hill_domain = 0x68696C6Cu;    // "hill"
constexpr std::uint32_t valley_domain = 0x76616C65u;  // "vale"

}  // namespace

LandscapeTerrain::LandscapeTerrain(const LandscapeTerrainSpec& spec, std::uint32_t seed)
    : spec_(spec), hill_seed_(hash32(seed, hill_domain)), valley_seed_(hash32(seed, valley_domain)) {}

// Zero on the hills, down to -depth on the floor; (1 - d²)² keeps the slope continuous where the
// valley's sides meet the hills.
float LandscapeTerrain::valley(float x, float z) const {
  const float floor_z = spec_.valley_meander * (2.0f * value_noise(valley_seed_, x / spec_.valley_wavelength) - 1.0f);
  const float d = (z - floor_z) / spec_.valley_width;
  const float w = std::max(0.0f, 1.0f - d * d);
  return -spec_.valley_depth * w * w;
}

float LandscapeTerrain::height(float x, float z) const {
  const float hills = spec_.relief * (fractal_noise(hill_seed_, spec_.octaves, x / spec_.feature, z / spec_.feature) - 0.5f);
  return hills + valley(x, z);
}

glm::vec3 LandscapeTerrain::normal(float x, float z, float step) const {
  return glm::normalize(glm::vec3(height(x - step, z) - height(x + step, z), 2.0f * step, height(x, z - step) - height(x, z + step)));
}

}  // namespace pointgen
