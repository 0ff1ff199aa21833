#include "pointgen/landscape/landscape_cells.hpp"

#include "pointgen/instance_table.hpp"
#include "pointgen/landscape/growth_rules.hpp"
#include "pointgen/landscape/hash32.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace pointgen {
namespace {

constexpr std::uint32_t site_domain = 0x73697465u;  // "site"
constexpr std::uint32_t far_domain = 0x66617221u;   // "far!"

// What each of a site's uniforms decides: its own hash input, so that a rule added to one never
// moves another. Two sites whose 32-bit keys agree (any two, once in four billion) draw alike: the same
// jitter in their own cells, the same turn and tint.
enum SiteDraw : std::uint32_t { taken_draw, species_draw, jitter_x_draw, jitter_z_draw, turn_draw, scale_draw, tint_draw, seed_draw = tint_draw + 3 };

struct Site {
  std::uint32_t key;
  float draw(SiteDraw d) const { return unit_float(hash32(key, d)); }
};

const LandscapeLayer& layer_of(const LandscapeSpec& spec, const CellKey& key) { return spec.layers[static_cast<std::size_t>(key.layer)]; }

bool in_landscape(const LandscapeSpec& spec, const CellKey& key) {
  if (key.layer < 0 || static_cast<std::size_t>(key.layer) >= spec.layers.size()) return false;
  const glm::ivec2 count = cell_count(spec, key.layer);
  return key.x >= 0 && key.z >= 0 && key.x < count.x && key.z < count.y;
}

// Species by weight: the first whose running sum of weights passes u × the sum.
int pick_species(const LandscapeLayer& layer, float u) {
  const float total = layer.total_weight();
  float running = 0.0f;
  for (std::size_t s = 0; s + 1 < layer.species.size(); ++s) {
    running += layer.species[s].weight;
    if (u * total < running) return static_cast<int>(s);
  }
  return static_cast<int>(layer.species.size()) - 1;
}

// Rounding at 50 km from the origin may carry a site a hair past its cell's far edge.
glm::vec2 site_position(const CellBounds& bounds, float cell_size, const CellSites& sites, int index, const Site& site) {
  const float step = cell_size / static_cast<float>(sites.per_side);
  const glm::vec2 grid(static_cast<float>(index % sites.per_side), static_cast<float>(index / sites.per_side));
  const glm::vec2 p = bounds.min + step * (grid + glm::vec2(site.draw(jitter_x_draw), site.draw(jitter_z_draw)));
  return glm::min(p, bounds.max);
}

LandscapePlant make_plant(const LandscapeSpecies& s, int species, const glm::vec3& at, const Site& site) {
  const float turn = glm::two_pi<float>() * site.draw(turn_draw);
  const float scale = s.scale.x + (s.scale.y - s.scale.x) * site.draw(scale_draw);
  const float cosine = scale * std::cos(turn), sine = scale * std::sin(turn);
  glm::vec3 tint;
  for (int channel = 0; channel < 3; ++channel) {
    tint[channel] = 1.0f + s.tint_spread * (2.0f * site.draw(static_cast<SiteDraw>(tint_draw + channel)) - 1.0f);
  }
  // Turned about +Y as glm::rotate turns, then scaled alike on every axis.
  const glm::mat4x3 transform(glm::vec3(cosine, 0.0f, -sine), glm::vec3(0.0f, scale, 0.0f), glm::vec3(sine, 0.0f, cosine), at);
  return {transform, pack_tint(tint), hash32(site.key, seed_draw), static_cast<std::uint32_t>(species)};
}

// The share of probes × probes points spread over `area` where the species grows.
float growing_share(const LandscapeSpec& spec, const LandscapeTerrain& terrain, int layer, int species, const CellBounds& area,
                    int probes) {
  int growing = 0;
  for (int probe = 0; probe < probes * probes; ++probe) {
    const glm::vec2 p = area.min + (area.max - area.min) * (glm::vec2(probe % probes, probe / probes) + 0.5f) / static_cast<float>(probes);
    growing += grows_at(spec, terrain, layer, species, p, terrain.height(p.x, p.y)) ? 1 : 0;
  }
  return static_cast<float>(growing) / static_cast<float>(probes * probes);
}

}  // namespace

glm::ivec2 cell_count(const LandscapeSpec& spec, int layer) {
  return glm::ivec2(glm::ceil(spec.size / spec.layers[static_cast<std::size_t>(layer)].cell_size));
}

CellBounds cell_bounds(const LandscapeSpec& spec, const CellKey& key) {
  const float side = layer_of(spec, key).cell_size;
  const glm::vec2 origin = -0.5f * spec.size;
  return {origin + side * glm::vec2(key.x, key.z), origin + side * glm::vec2(key.x + 1, key.z + 1)};
}

CellRange cell_range(const LandscapeSpec& spec, int layer, glm::vec2 center, float radius) {
  const float side = spec.layers[static_cast<std::size_t>(layer)].cell_size;
  const glm::vec2 origin = -0.5f * spec.size;
  const glm::ivec2 last = cell_count(spec, layer) - 1;
  return {glm::clamp(glm::ivec2(glm::floor((center - radius - origin) / side)), glm::ivec2(0), last),
          glm::clamp(glm::ivec2(glm::floor((center + radius - origin) / side)), glm::ivec2(0), last)};
}

std::vector<CellKey> cells_within(const LandscapeSpec& spec, int layer, glm::vec2 center, float radius) {
  const CellRange range = cell_range(spec, layer, center, radius);
  std::vector<CellKey> keys;
  for (int z = range.lo.y; z <= range.hi.y; ++z) {
    for (int x = range.lo.x; x <= range.hi.x; ++x) {
      const CellBounds bounds = cell_bounds(spec, {layer, x, z});
      if (glm::distance(glm::clamp(center, bounds.min, bounds.max), center) <= radius) keys.push_back({layer, x, z});
    }
  }
  return keys;
}

CellSites cell_sites(const LandscapeLayer& layer) {
  const float expected = layer.density * layer.cell_size * layer.cell_size;
  if (expected <= 0.0f || layer.species.empty()) return {};
  const int per_side = std::max(1, static_cast<int>(std::ceil(std::sqrt(expected))));
  return {per_side, std::min(1.0f, expected / static_cast<float>(per_side * per_side))};
}

std::vector<LandscapePlant> generate_cell(const LandscapeSpec& spec, const CellKey& key) {
  if (!in_landscape(spec, key)) return {};
  const LandscapeLayer& layer = layer_of(spec, key);
  const CellSites sites = cell_sites(layer);
  const CellBounds bounds = cell_bounds(spec, key);
  const glm::vec2 area = 0.5f * spec.size;
  const LandscapeTerrain terrain(spec.terrain, spec.seed);
  std::vector<LandscapePlant> plants;
  plants.reserve(static_cast<std::size_t>(sites.count()));
  for (int index = 0; index < sites.count(); ++index) {
    const Site site{hash32(spec.seed, site_domain, key.layer, key.x, key.z, index)};
    if (site.draw(taken_draw) >= sites.probability) continue;
    const glm::vec2 p = site_position(bounds, layer.cell_size, sites, index, site);
    if (glm::any(glm::greaterThan(glm::abs(p), area))) continue;
    const int species = pick_species(layer, site.draw(species_draw));
    const float height = terrain.height(p.x, p.y);
    if (!grows_at(spec, terrain, key.layer, species, p, height)) continue;
    plants.push_back(make_plant(layer.species[static_cast<std::size_t>(species)], species, {p.x, height, p.y}, site));
  }
  return plants;
}

// Over a uniform [a, b], the mean of the scale's square is (a² + ab + b²) / 3.
float mean_square_scale(const LandscapeSpecies& s) { return (s.scale.x * s.scale.x + s.scale.x * s.scale.y + s.scale.y * s.scale.y) / 3.0f; }

CellBounds far_block_bounds(const LandscapeSpec& spec, const FarBlockKey& key) {
  const float side = layer_of(spec, {key.layer, 0, 0}).cell_size * static_cast<float>(1 << key.level);
  const glm::vec2 origin = -0.5f * spec.size + side * glm::vec2(key.x, key.z);
  return {origin, glm::min(origin + side, 0.5f * spec.size)};
}

float open_surface_density(const LandscapeSpec& spec, int layer) {
  const LandscapeLayer& l = spec.layers[static_cast<std::size_t>(layer)];
  float per_plant = 0.0f;
  for (const LandscapeSpecies& s : l.species) per_plant += s.weight / l.total_weight() * s.surface * mean_square_scale(s);
  return l.density * per_plant;
}

float mean_height(const LandscapeSpec& spec, int layer) {
  const LandscapeLayer& l = spec.layers[static_cast<std::size_t>(layer)];
  float height = 0.0f;
  for (const LandscapeSpecies& s : l.species) height += s.weight / l.total_weight() * s.height * 0.5f * (s.scale.x + s.scale.y);
  return height;
}

std::optional<LandscapePlant> far_candidate(const LandscapeSpec& spec, const FarBlockKey& key, std::uint32_t index) {
  const LandscapeLayer& layer = layer_of(spec, {key.layer, 0, 0});
  const Site site{hash32(spec.seed, far_domain, key.layer, key.level, key.x, key.z, index)};
  float total = 0.0f;
  for (const LandscapeSpecies& s : layer.species) total += s.weight * s.surface * mean_square_scale(s);
  float running = 0.0f;
  int species = static_cast<int>(layer.species.size()) - 1;
  for (std::size_t s = 0; s + 1 < layer.species.size(); ++s) {
    running += layer.species[s].weight * layer.species[s].surface * mean_square_scale(layer.species[s]);
    if (site.draw(species_draw) * total < running) {
      species = static_cast<int>(s);
      break;
    }
  }
  const CellBounds b = far_block_bounds(spec, key);
  const glm::vec2 p = glm::min(b.min + (b.max - b.min) * glm::vec2(site.draw(jitter_x_draw), site.draw(jitter_z_draw)), b.max);
  const LandscapeTerrain terrain(spec.terrain, spec.seed);
  const float height = terrain.height(p.x, p.y);
  if (!grows_at(spec, terrain, key.layer, species, p, height)) return std::nullopt;
  return make_plant(layer.species[static_cast<std::size_t>(species)], species, {p.x, height, p.y}, site);
}

float expected_surface(const LandscapeSpec& spec, const CellKey& key) {
  if (!in_landscape(spec, key)) return 0.0f;
  const LandscapeLayer& layer = layer_of(spec, key);
  const CellBounds bounds = cell_bounds(spec, key);
  const CellBounds inside{glm::max(bounds.min, -0.5f * spec.size), glm::min(bounds.max, 0.5f * spec.size)};
  const LandscapeTerrain terrain(spec.terrain, spec.seed);
  float per_plant = 0.0f;
  for (std::size_t s = 0; s < layer.species.size(); ++s) {
    const LandscapeSpecies& species = layer.species[s];
    per_plant += species.weight / layer.total_weight() * growing_share(spec, terrain, key.layer, static_cast<int>(s), inside, 4) *
                 species.surface * mean_square_scale(species);
  }
  const glm::vec2 extent = inside.max - inside.min;
  return layer.density * extent.x * extent.y * per_plant;
}

double expected_plant_count(const LandscapeSpec& spec) {
  // 64 × 64 probes: the share of each species' ground to about a percent, in some milliseconds
  // however large the landscape.
  constexpr int probes = 64;
  const LandscapeTerrain terrain(spec.terrain, spec.seed);
  const CellBounds area{-0.5f * spec.size, 0.5f * spec.size};
  double plants = 0.0;
  for (std::size_t l = 0; l < spec.layers.size(); ++l) {
    const LandscapeLayer& layer = spec.layers[l];
    double share = 0.0;
    for (std::size_t s = 0; s < layer.species.size(); ++s) {
      share += layer.species[s].weight / layer.total_weight() *
               growing_share(spec, terrain, static_cast<int>(l), static_cast<int>(s), area, probes);
    }
    plants += static_cast<double>(layer.density) * spec.size.x * spec.size.y * share;
  }
  return plants;
}

}  // namespace pointgen
