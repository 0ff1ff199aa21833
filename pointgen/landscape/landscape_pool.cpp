#include "pointgen/landscape/landscape_pool.hpp"

#include "pointgen/landscape/hash32.hpp"
#include "pointgen/landscape/landscape_terrain.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace pointgen {

namespace {

constexpr std::uint32_t sparse_domain = 0x73706172u;  // "spar"
constexpr std::uint32_t band_domain = 0x62616E64u;    // "band"
// Across the band, a cell's plants thin out by its distance while its far block's candidates grow,
// in eighths, so that plants give way to candidates a few at a time as the eye moves instead of a
// cell at once.
constexpr int band_steps = 8;

// The eighths of a cell's plants kept `near` metres from the eye; its block takes the rest.
int kept_steps(float near, float reach) {
  const float end = (1.0f + LandscapePool::band) * reach;
  return std::clamp(static_cast<int>(std::lround(band_steps * (end - near) / (LandscapePool::band * reach))), 0, band_steps);
}

// Whether a plant of a cell keeping `steps` eighths is kept: by its own hash, so that the plants
// kept at n eighths are among those kept at n + 1.
bool kept(const LandscapePlant& plant, int steps) {
  return steps >= band_steps || unit_float(hash32(plant.seed, band_domain)) * band_steps < static_cast<float>(steps);
}

// Metres above the highest hill a plant may reach, for culling blocks against the view.
constexpr float tallest_plant = 100.0f;
// A far block is split while wider than this share of its distance from the eye: the density
// formula's distance is the block centre's, within about a fifth of any of its plants'.
constexpr float block_share_of_distance = 0.25f;
// A block's candidates come in steps of a quarter octave, so that the eye moving a little changes
// few blocks.
constexpr float steps_an_octave = 4.0f;

float distance_to(glm::vec2 p, const CellBounds& b) { return glm::distance(glm::clamp(p, b.min, b.max), p); }

// Whether any of the box's corners may be seen: not all beyond one plane of the clip volume.
bool in_view(const glm::mat4& view_projection, const glm::vec3& lo, const glm::vec3& hi) {
  std::array<glm::vec4, 8> clip;
  for (int c = 0; c < 8; ++c) {
    clip[static_cast<std::size_t>(c)] = view_projection * glm::vec4((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z, 1.0f);
  }
  for (int axis = 0; axis < 3; ++axis) {
    for (const float sign : {-1.0f, 1.0f}) {
      const bool outside = std::all_of(clip.begin(), clip.end(), [&](const glm::vec4& p) { return sign * p[axis] > p.w; });
      if (outside) return false;
    }
  }
  return true;
}

// The candidates for n points: n rounded to the nearest quarter octave; below one, one candidate
// with probability n (by the block's own hash), so that far blocks are drawn on average as asked.
std::uint32_t candidates_for(float n, std::uint32_t block_hash) {
  if (n < 1.0f) return unit_float(block_hash) < n ? 1u : 0u;
  const float steps = std::round(steps_an_octave * std::log2(n));
  return static_cast<std::uint32_t>(std::lround(std::exp2(steps / steps_an_octave)));
}

}  // namespace

void LandscapePool::Stats::add(const Stats& other) {
  cells += other.cells;
  plants += other.plants;
  cells_made += other.cells_made;
  plants_made += other.plants_made;
  cells_left_out += other.cells_left_out;
  plants_kept += other.plants_kept;
  blocks += other.blocks;
  far_plants += other.far_plants;
  far_share = std::min(far_share, other.far_share);
}

LandscapePool::LandscapePool(LandscapeSpec spec, std::vector<float> reach, std::vector<std::size_t> meshes, std::size_t capacity)
    : spec_(std::move(spec)), reach_(std::move(reach)), meshes_(std::move(meshes)), capacity_(capacity) {
  if (reach_.size() != spec_.layers.size()) throw std::invalid_argument("a reach for each layer");
  std::size_t species = 0;
  for (const LandscapeLayer& layer : spec_.layers) {
    first_species_.push_back(species);
    species += layer.species.size();
  }
  if (meshes_.size() != species) throw std::invalid_argument("a mesh for each species");
}

std::size_t LandscapePool::most_plants_in_reach(const LandscapeSpec& spec, const std::vector<float>& reach) {
  double plants = 0.0;
  for (std::size_t layer = 0; layer < spec.layers.size(); ++layer) {
    // A disc of radius r meets at most (2r / side + 2)² cells along each axis's grid lines; the
    // cells of the band beyond the reach count too.
    const double across = std::floor(2.0 * (1.0 + band) * reach[layer] / spec.layers[layer].cell_size) + 2.0;
    const glm::ivec2 count = cell_count(spec, static_cast<int>(layer));
    const double cells = std::min(across, static_cast<double>(count.x)) * std::min(across, static_cast<double>(count.y));
    plants += cells * cell_sites(spec.layers[layer]).count();
  }
  return static_cast<std::size_t>(std::min(plants, 1e15));
}

std::vector<LandscapePool::NearCell> LandscapePool::take_near_cells(glm::vec2 eye, bool banded) {
  struct Near {
    float distance;
    CellKey key;
    auto operator<=>(const Near&) const = default;
  };
  std::vector<Near> near;
  for (std::size_t layer = 0; layer < spec_.layers.size(); ++layer) {
    const float radius = (banded ? 1.0f + band : 1.0f) * reach_[layer];
    for (const CellKey& key : cells_within(spec_, static_cast<int>(layer), eye, radius)) {
      near.push_back({distance_to(eye, cell_bounds(spec_, key)), key});
    }
  }
  std::sort(near.begin(), near.end());
  std::vector<NearCell> chosen;
  for (std::size_t i = 0; i < near.size(); ++i) {
    const int steps = banded ? kept_steps(near[i].distance, reach_[static_cast<std::size_t>(near[i].key.layer)]) : band_steps;
    if (steps == 0) continue;
    const std::vector<LandscapePlant>& plants = plants_of(near[i].key);
    const auto count = static_cast<std::size_t>(std::count_if(plants.begin(), plants.end(), [&](const LandscapePlant& p) { return kept(p, steps); }));
    if (stats_.plants + count > capacity_) {
      stats_.cells_left_out = near.size() - i;
      break;
    }
    stats_.plants += count;
    chosen.push_back({near[i].key, steps});
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

std::vector<LandscapePool::Block> LandscapePool::take_far_blocks(const LandscapeView& view) {
  const std::size_t room = capacity_ - stats_.plants;
  std::vector<Block> blocks;
  for (int layer = 0; layer < static_cast<int>(spec_.layers.size()); ++layer) add_far_blocks(view, layer, 1.0f, blocks);
  std::size_t asked = 0;
  for (const Block& block : blocks) asked += block.candidates;
  if (asked > room) {  // fewer points for every block, rather than none for the farthest
    stats_.far_share = static_cast<float>(room) / static_cast<float>(asked);
    blocks.clear();
    for (int layer = 0; layer < static_cast<int>(spec_.layers.size()); ++layer) add_far_blocks(view, layer, stats_.far_share, blocks);
  }
  std::sort(blocks.begin(), blocks.end());
  std::vector<Block> taken;
  for (const Block& block : blocks) {
    const std::size_t plants = plants_of(block);
    if (stats_.plants + plants > capacity_) {  // rounding may ask a few more than the share
      ++stats_.cells_left_out;
      continue;
    }
    stats_.plants += plants;
    stats_.far_plants += block.whole ? 0 : plants;
    taken.push_back(block);
  }
  return taken;
}

void LandscapePool::add_far_blocks(const LandscapeView& view, int layer, float share, std::vector<Block>& into) const {
  const float density = open_surface_density(spec_, layer), height = mean_height(spec_, layer);
  if (density <= 0.0f || view.points_at_a_metre <= 0.0f) return;
  const glm::ivec2 count = cell_count(spec_, layer);
  int top = 0;
  while ((1 << top) < std::max(count.x, count.y)) ++top;
  const LandscapeTerrain terrain(spec_.terrain, spec_.seed);
  const float lowest = -0.5f * spec_.terrain.relief - spec_.terrain.valley_depth;
  const float highest = 0.5f * spec_.terrain.relief + tallest_plant;
  const glm::vec2 eye(view.eye.x, view.eye.z);
  const float reach = reach_[static_cast<std::size_t>(layer)];
  std::vector<FarBlockKey> open{{layer, top, 0, 0}};
  while (!open.empty()) {
    const FarBlockKey key = open.back();
    open.pop_back();
    const CellBounds b = far_block_bounds(spec_, key);
    if (b.min.x >= b.max.x || b.min.y >= b.max.y) continue;  // past the area
    if (!in_view(view.view_projection, {b.min.x, lowest, b.min.y}, {b.max.x, highest, b.max.y})) continue;
    const float near = distance_to(eye, b);
    const float side = std::max(b.max.x - b.min.x, b.max.y - b.min.y);
    const int steps_made_whole = key.level == 0 ? kept_steps(near, reach) : 0;
    if (steps_made_whole == band_steps) continue;  // a cell made whole
    if (key.level > 0 && (near <= (1.0f + band) * reach || side > block_share_of_distance * near)) {
      for (int child = 0; child < 4; ++child) open.push_back({layer, key.level - 1, 2 * key.x + (child & 1), 2 * key.z + (child >> 1)});
      continue;
    }
    const glm::vec2 center = 0.5f * (b.min + b.max);
    const float ground = terrain.height(center.x, center.y);
    const float d = std::max(glm::distance(view.eye, glm::vec3(center.x, ground, center.y)), side);
    const float area = (b.max.x - b.min.x) * (b.max.y - b.min.y);
    // The plants of a block overlap each other on the screen: it asks no more than k points a
    // pixel of its ground as the eye sees it, and of its plants' height seen from the side.
    const float sine = std::clamp((view.eye.y - ground) / d, 0.0f, 1.0f);
    const float seen = area * sine + side * height * std::sqrt(1.0f - sine * sine);
    const float rest = 1.0f - static_cast<float>(steps_made_whole) / band_steps;  // of a cell in the band
    const float points = rest * share * view.points_at_a_metre * std::min(density * area, 2.0f * seen) / (d * d);
    // Never more candidates than the block has sites: where its plants ask a point or more each,
    // each candidate draws what its plant asks.
    const auto sites = static_cast<std::uint32_t>(std::ceil(spec_.layers[static_cast<std::size_t>(layer)].density * area));
    const std::uint32_t candidates = candidates_for(points, hash32(spec_.seed, sparse_domain, key.layer, key.level, key.x, key.z));
    if (candidates > 0) into.push_back({key, std::min(candidates, sites), candidates >= sites});
  }
}

const std::vector<LandscapePlant>& LandscapePool::plants_of(const CellKey& key) {
  auto [at, made] = kept_.try_emplace(key);
  if (made) {
    at->second.plants = generate_cell(spec_, key);
    kept_plants_ += at->second.plants.size();
    ++stats_.cells_made;
    stats_.plants_made += at->second.plants.size();
  }
  at->second.used = fills_;
  return at->second.plants;
}

std::size_t LandscapePool::plants_of(const Block& block) {
  KeptBlock& kept = kept_blocks_[block.key];
  for (; kept.candidates < block.candidates; ++kept.candidates) {
    if (std::optional<LandscapePlant> plant = far_candidate(spec_, block.key, kept.candidates)) {
      kept.plants.push_back(*plant);
      kept.indices.push_back(kept.candidates);
      ++kept_plants_;
      ++stats_.plants_made;
    }
  }
  kept.used = fills_;
  return static_cast<std::size_t>(std::lower_bound(kept.indices.begin(), kept.indices.end(), block.candidates) - kept.indices.begin());
}

bool LandscapePool::fill(const LandscapeView& view) {
  ++fills_;
  stats_ = {};
  // No band without far blocks: the cells within reach are all there is.
  std::vector<NearCell> chosen = take_near_cells({view.eye.x, view.eye.z}, view.points_at_a_metre > 0.0f);
  std::vector<Block> blocks = take_far_blocks(view);
  stats_.cells = chosen.size();
  stats_.blocks = blocks.size();
  forget_least_recently_used();
  stats_.plants_kept = kept_plants_;
  if (chosen == chosen_ && blocks == chosen_blocks_) return false;
  chosen_ = std::move(chosen);
  chosen_blocks_ = std::move(blocks);
  return true;
}

// Beyond twice the capacity, the cells and blocks chosen longest ago go; this fill's stay.
void LandscapePool::forget_least_recently_used() {
  if (kept_plants_ <= 2 * capacity_) return;
  struct Old {
    std::uint64_t used;
    std::optional<CellKey> cell;
    FarBlockKey block;
    bool operator<(const Old& o) const { return used < o.used; }
  };
  std::vector<Old> by_use;
  for (const auto& [key, kept] : kept_) {
    if (kept.used != fills_) by_use.push_back({kept.used, key, {}});
  }
  for (const auto& [key, kept] : kept_blocks_) {
    if (kept.used != fills_) by_use.push_back({kept.used, std::nullopt, key});
  }
  std::stable_sort(by_use.begin(), by_use.end());
  for (const Old& old : by_use) {
    if (kept_plants_ <= capacity_) break;
    if (old.cell) {
      const auto at = kept_.find(*old.cell);
      kept_plants_ -= at->second.plants.size();
      kept_.erase(at);
    } else {
      const auto at = kept_blocks_.find(old.block);
      kept_plants_ -= at->second.plants.size();
      kept_blocks_.erase(at);
    }
  }
}

std::vector<InstanceTable> LandscapePool::tables() const {
  std::vector<InstanceTable> tables;
  for (std::size_t mesh : meshes_) tables.push_back({mesh, {}, {}, {}});
  for (std::size_t mesh : meshes_) tables.push_back({mesh, {}, {}, {}, true});
  const auto add = [&](std::size_t table, const LandscapePlant& plant) {
    tables[table].transforms.push_back(plant.transform);
    tables[table].tints.push_back(plant.tint);
    tables[table].seeds.push_back(plant.seed);
  };
  for (const NearCell& cell : chosen_) {
    for (const LandscapePlant& plant : kept_.at(cell.key).plants) {
      if (kept(plant, cell.steps)) add(first_species_[static_cast<std::size_t>(cell.key.layer)] + plant.species, plant);
    }
  }
  for (const Block& block : chosen_blocks_) {
    const KeptBlock& kept = kept_blocks_.at(block.key);
    const std::size_t first = (block.whole ? 0 : meshes_.size()) + first_species_[static_cast<std::size_t>(block.key.layer)];
    for (std::size_t i = 0; i < kept.indices.size() && kept.indices[i] < block.candidates; ++i) add(first + kept.plants[i].species, kept.plants[i]);
  }
  return tables;
}

}  // namespace pointgen
