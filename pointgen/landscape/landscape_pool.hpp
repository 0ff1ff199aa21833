#pragma once
#include "pointgen/instance_table.hpp"
#include "pointgen/landscape/landscape_cells.hpp"

#include <cstdint>
#include <map>
#include <vector>

namespace pointgen {

// The plants a landscape shows from one place: of each layer the cells reaching within the
// layer's reach of the eye, nearest first, as many as `capacity` plants hold. The tables follow
// from the eye alone, whatever was asked before: made cells are kept (the least recently used go
// first beyond twice the capacity) only so that the next eye need not make them again.
class LandscapePool {
 public:
  // `reach` per layer (metres); `meshes` per species, layer after layer: the tables' meshes.
  LandscapePool(LandscapeSpec spec, std::vector<float> reach, std::vector<std::size_t> meshes, std::size_t capacity);

  // Chooses the cells for an eye at (x, z); whether they changed since the last fill.
  bool fill(glm::vec2 eye);
  // Per species, layer after layer: the chosen cells' plants, cell by cell in key order. Made
  // anew, so that the caller keeps them.
  std::vector<InstanceTable> tables() const;

  struct Stats {
    std::size_t cells = 0;           // chosen
    std::size_t plants = 0;          // in the chosen cells
    std::size_t cells_made = 0;      // by this fill, not found kept
    std::size_t plants_made = 0;     // in those
    std::size_t cells_left_out = 0;  // within reach but past the capacity
    std::size_t plants_kept = 0;     // in the made cells held after this fill
  };
  const Stats& stats() const { return stats_; }
  std::size_t capacity() const { return capacity_; }

  // The most plants the cells within every layer's reach of any one eye can hold (every site
  // taken): a pool this large never leaves a cell out.
  static std::size_t most_plants_in_reach(const LandscapeSpec& spec, const std::vector<float>& reach);

 private:
  struct Kept {
    std::vector<LandscapePlant> plants;
    std::uint64_t used = 0;  // the fill that last chose it
  };
  const std::vector<LandscapePlant>& plants_of(const CellKey& key);
  void forget_least_recently_used();

  LandscapeSpec spec_;
  std::vector<float> reach_;
  std::vector<std::size_t> meshes_;
  std::vector<std::size_t> first_species_;  // per layer, its first table
  std::size_t capacity_;
  std::vector<CellKey> chosen_;  // in key order
  std::map<CellKey, Kept> kept_;
  std::size_t kept_plants_ = 0;
  std::uint64_t fills_ = 0;
  Stats stats_;
};

}  // namespace pointgen
