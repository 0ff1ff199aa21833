#pragma once
#include "pointgen/landscape/landscape_spec.hpp"

#include <glm/glm.hpp>

#include <compare>
#include <cstdint>
#include <optional>
#include <vector>

namespace pointgen {

// A cell of one layer: cell (0, 0) has its corner at the area's (-x, -z) corner.
struct CellKey {
  int layer = 0;
  std::int32_t x = 0, z = 0;
  auto operator<=>(const CellKey&) const = default;
};

struct CellBounds {
  glm::vec2 min, max;  // in x and z
};

// One plant as the renderer's instance tables keep it (InstanceTable's transform, tint and seed),
// with its species, numbered within its cell's layer.
struct LandscapePlant {
  glm::mat4x3 transform;
  std::uint32_t tint;  // pack_tint's
  std::uint32_t seed;
  std::uint32_t species;
};
static_assert(sizeof(LandscapePlant) == 60, "no padding: plants made alike are alike byte for byte");

// Cells along x and z in `layer`; the last row and column may reach past the area, where no plant
// grows.
glm::ivec2 cell_count(const LandscapeSpec& spec, int layer);
CellBounds cell_bounds(const LandscapeSpec& spec, const CellKey& key);

// The index rectangle of a layer's cells that may reach within `radius` of `center`, clamped to
// the landscape: its size bounds what cells_within lists before any cell is visited.
struct CellRange {
  glm::ivec2 lo, hi;
  double count() const { return static_cast<double>(hi.x - lo.x + 1) * static_cast<double>(hi.y - lo.y + 1); }
};
CellRange cell_range(const LandscapeSpec& spec, int layer, glm::vec2 center, float radius);

// The cells of `layer` that reach within `radius` of `center` (x, z), row by row.
std::vector<CellKey> cells_within(const LandscapeSpec& spec, int layer, glm::vec2 center, float radius);

// A cell's candidate sites: a jittered grid of n × n (n² just above density × area), each site
// taken with the probability that makes density × area the expected count.
struct CellSites {
  int per_side = 0;
  float probability = 0.0f;  // that a site is taken
  int count() const { return per_side * per_side; }
};
CellSites cell_sites(const LandscapeLayer& layer);

// The cell's plants, each from hash32(seed, layer, x, z, site) and the terrain alone: the same
// bytes whatever was made before, in whichever order, on whichever thread. Empty for a key
// outside the landscape.
std::vector<LandscapePlant> generate_cell(const LandscapeSpec& spec, const CellKey& key);

// A far block of a layer's cells (2^level × 2^level of them from cell (x, z) · 2^level on) is
// drawn by candidates instead of its plants (LandscapePool): candidate `index` stands anywhere in
// the block, of a species picked by its share of the layer's surface were every species to grow
// everywhere (weight × surface × mean squared scale); nothing where that species does not grow.
// So candidates that become plants follow the layer's surface where it grows, each from
// hash32(seed, layer, level, x, z, index) alone.
struct FarBlockKey {
  int layer = 0, level = 0;
  std::int32_t x = 0, z = 0;
  auto operator<=>(const FarBlockKey&) const = default;
};
CellBounds far_block_bounds(const LandscapeSpec& spec, const FarBlockKey& key);  // clamped to the area
std::optional<LandscapePlant> far_candidate(const LandscapeSpec& spec, const FarBlockKey& key, std::uint32_t index);
// m² of the layer's plants' surface per m² of ground were every species to grow everywhere: the
// candidates a block needs for n points a square metre of surface.
float open_surface_density(const LandscapeSpec& spec, int layer);
// The layer's plants' mean height in metres, by the species' weights and mean scales.
float mean_height(const LandscapeSpec& spec, int layer);

// The plants' expected surface in m² (count × each species' surface × its mean squared scale),
// with each species' rules probed at 4 × 4 points instead of at every site: for cells too far to
// make.
float expected_surface(const LandscapeSpec& spec, const CellKey& key);

// The plants the whole landscape stands for, had every cell been made: each layer's density over
// the area, times the share of it where each species grows (probed, not made).
double expected_plant_count(const LandscapeSpec& spec);

}  // namespace pointgen
