#include "pointgen/landscape/growth_rules.hpp"

#include "pointgen/landscape/hash32.hpp"
#include "pointgen/landscape/value_noise.hpp"

#include <cmath>

namespace pointgen {
namespace {

constexpr std::uint32_t grove_domain = 0x67726F76u;  // "grov"
constexpr int grove_octaves = 3;

const LandscapeSpecies& species_of(const LandscapeSpec& spec, int layer, int species) {
  return spec.layers[static_cast<std::size_t>(layer)].species[static_cast<std::size_t>(species)];
}

}  // namespace

float grove_noise(const LandscapeSpec& spec, int layer, int species, glm::vec2 p) {
  const float size = species_of(spec, layer, species).grove_size;
  return fractal_noise(hash32(spec.seed, grove_domain, layer, species), grove_octaves, p.x / size, p.y / size);
}

bool grows_at(const LandscapeSpec& spec, const LandscapeTerrain& terrain, int layer, int species, glm::vec2 p, float height) {
  const LandscapeSpecies& s = species_of(spec, layer, species);
  if (height < s.altitude.x || height > s.altitude.y) return false;
  if (s.grove > 0.0f && grove_noise(spec, layer, species, p) < s.grove) return false;
  if (s.slope_max_deg >= 90.0f) return true;
  return terrain.normal(p.x, p.y).y >= std::cos(glm::radians(s.slope_max_deg));
}

}  // namespace pointgen
