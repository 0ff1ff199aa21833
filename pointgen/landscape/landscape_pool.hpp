#pragma once
#include "pointgen/instance_table.hpp"
#include "pointgen/landscape/landscape_cells.hpp"

#include <cstdint>
#include <map>
#include <vector>

namespace pointgen {

// What a frame asks of a landscape: where the eye is, what it sees (a world → clip matrix), and
// how many points a square metre of plant surface asks a metre away (k × pixels per radian² × an
// average facing of one half); none: no far blocks.
struct LandscapeView {
  glm::vec3 eye{0.0f};
  glm::mat4 view_projection{1.0f};
  float points_at_a_metre = 0.0f;
};

// The plants a landscape shows from one place. Of each layer, the cells reaching within the
// layer's reach of the eye are made whole, and across a band a quarter as wide beyond it they
// thin out as their far blocks' candidates grow; beyond it, the cells the view sees are taken in
// blocks of 2^level × 2^level cells, each at most a quarter of its distance across, and each
// block is drawn by as many candidates as points its surface asks (far_candidate): plants that
// round up to one point each (InstanceTable::rounds_up), so that a block costs its points, not
// its plants. Cells are taken nearest first, as many as `capacity` plants hold; the blocks share
// what is left, each with fewer candidates where they would not all fit. The
// tables follow from the view alone, whatever was asked before: made cells and candidates are
// kept (the least recently used go first beyond twice the capacity) only so that the next view
// need not make them again.
class LandscapePool {
 public:
  // `reach` per layer (metres); `meshes` per species, layer after layer: the tables' meshes.
  LandscapePool(LandscapeSpec spec, std::vector<float> reach, std::vector<std::size_t> meshes, std::size_t capacity);

  // Chooses the cells and blocks for a view; whether they changed since the last fill.
  bool fill(const LandscapeView& view);
  // Per species, layer after layer, the chosen cells' plants cell by cell in key order, and the
  // whole blocks' block by block; then per species the other far blocks' plants, block by block.
  // Made anew, so that the caller keeps them.
  std::vector<InstanceTable> tables() const;
  std::size_t table_count() const { return 2 * meshes_.size(); }

  struct Stats {
    std::size_t cells = 0;           // made whole, chosen
    std::size_t plants = 0;          // in the chosen cells and blocks
    std::size_t cells_made = 0;      // by this fill, not found kept
    std::size_t plants_made = 0;     // in those, and the blocks' new candidates that grew
    std::size_t cells_left_out = 0;  // cells within reach and blocks in view past the capacity
    std::size_t plants_kept = 0;     // in the made cells and blocks held after this fill
    std::size_t blocks = 0;          // far blocks chosen
    std::size_t far_plants = 0;      // in them, drawn a point each (not whole)
    // The share of the points far blocks ask that they draw: below 1 where the capacity left after
    // the near cells is too small, every block then drawing that share.
    float far_share = 1.0f;
    void add(const Stats& other);  // sums the counts, keeps the smaller share
  };
  const Stats& stats() const { return stats_; }
  // The far blocks chosen, in key order, and their candidates (the first of each one's sequence);
  // `whole` where they are as many as its sites, whose plants then ask a point or more each and
  // round as plants made whole do.
  struct Block {
    FarBlockKey key;
    std::uint32_t candidates;
    bool whole;
    auto operator<=>(const Block&) const = default;
  };
  const std::vector<Block>& blocks() const { return chosen_blocks_; }
  std::size_t capacity() const { return capacity_; }

  // The most plants the cells within every layer's reach of any one eye (and the band beyond it)
  // can hold, every site taken: a pool this large leaves no near cell out.
  static std::size_t most_plants_in_reach(const LandscapeSpec& spec, const std::vector<float>& reach);
  // The band beyond a layer's reach, as a share of the reach.
  static constexpr float band = 0.25f;
  // Room for far blocks' plants besides: a point each, 2.5 points a pixel over 200,000 pixels.
  static constexpr std::size_t far_plants = 1 << 19;

 private:
  struct Kept {
    std::vector<LandscapePlant> plants;
    std::uint64_t used = 0;  // the fill that last chose it
  };
  // A far block's candidates made so far, the first `candidates` of its sequence: those that
  // grew, and each one's index in the sequence.
  struct KeptBlock {
    std::vector<LandscapePlant> plants;
    std::vector<std::uint32_t> indices;
    std::uint32_t candidates = 0;
    std::uint64_t used = 0;
  };
  // The cells within reach, nearest first, as many as the capacity holds (in key order).
  // With `banded`, the band's cells too, each keeping some eighths of its plants.
  struct NearCell {
    CellKey key;
    int steps;  // eighths of its plants kept
    auto operator<=>(const NearCell&) const = default;
  };
  std::vector<NearCell> take_near_cells(glm::vec2 eye, bool banded);
  // The far blocks in view, with candidates for `share` of the points they ask (in key order).
  std::vector<Block> take_far_blocks(const LandscapeView& view);
  void add_far_blocks(const LandscapeView& view, int layer, float share, std::vector<Block>& into) const;
  const std::vector<LandscapePlant>& plants_of(const CellKey& key);
  std::size_t plants_of(const Block& block);  // makes its candidates; how many grew
  void forget_least_recently_used();

  LandscapeSpec spec_;
  std::vector<float> reach_;
  std::vector<std::size_t> meshes_;
  std::vector<std::size_t> first_species_;  // per layer, its first table
  std::size_t capacity_;
  std::vector<NearCell> chosen_;  // in key order
  std::vector<Block> chosen_blocks_;  // in key order
  std::map<CellKey, Kept> kept_;
  std::map<FarBlockKey, KeptBlock> kept_blocks_;
  std::size_t kept_plants_ = 0;
  std::uint64_t fills_ = 0;
  Stats stats_;
};

}  // namespace pointgen
