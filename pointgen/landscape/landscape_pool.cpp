#include "pointgen/landscape/landscape_pool.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pointgen {
namespace {

struct NearCell {
  float distance;
  CellKey key;
  auto operator<=>(const NearCell&) const = default;
};

// Every layer's cells within its reach of the eye, nearest first, ties in key order.
std::vector<NearCell> cells_by_distance(const LandscapeSpec& spec, const std::vector<float>& reach, glm::vec2 eye) {
  std::vector<NearCell> cells;
  for (std::size_t layer = 0; layer < spec.layers.size(); ++layer) {
    for (const CellKey& key : cells_within(spec, static_cast<int>(layer), eye, reach[layer])) {
      const CellBounds b = cell_bounds(spec, key);
      cells.push_back({glm::distance(glm::clamp(eye, b.min, b.max), eye), key});
    }
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

}  // namespace

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
    // A disc of radius r meets at most (2r / side + 2)² cells along each axis's grid lines.
    const double across = std::floor(2.0 * reach[layer] / spec.layers[layer].cell_size) + 2.0;
    const glm::ivec2 count = cell_count(spec, static_cast<int>(layer));
    const double cells = std::min(across, static_cast<double>(count.x)) * std::min(across, static_cast<double>(count.y));
    plants += cells * cell_sites(spec.layers[layer]).count();
  }
  return static_cast<std::size_t>(std::min(plants, 1e15));
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

bool LandscapePool::fill(glm::vec2 eye) {
  ++fills_;
  stats_ = {};
  std::vector<CellKey> chosen;
  const std::vector<NearCell> near = cells_by_distance(spec_, reach_, eye);
  for (std::size_t i = 0; i < near.size(); ++i) {
    const std::size_t plants = plants_of(near[i].key).size();
    if (stats_.plants + plants > capacity_) {
      stats_.cells_left_out = near.size() - i;
      break;
    }
    stats_.plants += plants;
    chosen.push_back(near[i].key);
  }
  std::sort(chosen.begin(), chosen.end());
  stats_.cells = chosen.size();
  forget_least_recently_used();
  stats_.plants_kept = kept_plants_;
  if (chosen == chosen_) return false;
  chosen_ = std::move(chosen);
  return true;
}

// Beyond twice the capacity, the cells chosen longest ago go; this fill's stay.
void LandscapePool::forget_least_recently_used() {
  if (kept_plants_ <= 2 * capacity_) return;
  std::vector<std::pair<std::uint64_t, CellKey>> by_use;
  for (const auto& [key, kept] : kept_) {
    if (kept.used != fills_) by_use.emplace_back(kept.used, key);
  }
  std::sort(by_use.begin(), by_use.end());
  for (const auto& [used, key] : by_use) {
    if (kept_plants_ <= capacity_) break;
    const auto at = kept_.find(key);
    kept_plants_ -= at->second.plants.size();
    kept_.erase(at);
  }
}

std::vector<InstanceTable> LandscapePool::tables() const {
  std::vector<InstanceTable> tables;
  for (std::size_t mesh : meshes_) tables.push_back({mesh, {}, {}, {}});
  for (const CellKey& key : chosen_) {
    for (const LandscapePlant& plant : kept_.at(key).plants) {
      InstanceTable& table = tables[first_species_[static_cast<std::size_t>(key.layer)] + plant.species];
      table.transforms.push_back(plant.transform);
      table.tints.push_back(plant.tint);
      table.seeds.push_back(plant.seed);
    }
  }
  return tables;
}

}  // namespace pointgen
