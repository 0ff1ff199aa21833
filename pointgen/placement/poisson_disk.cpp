#include "pointgen/placement/poisson_disk.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

namespace pointgen {
namespace {

constexpr int tile_cells = 32;  // a tile's side in grid cells: its points' grid stays in cache

// The background grid: cells of radius/√2 hold at most one point each, stored in place (an empty
// cell holds a point at infinity, which passes every distance test). A margin of two empty cells
// around the area lets the distance test read the 5×5 cells around any point without bounds.
class PointGrid {
 public:
  PointGrid(const glm::vec2& min, const glm::vec2& max, float radius)
      : min_(min), cell_(radius / std::sqrt(2.0f)), radius2_(radius * radius),
        cells_(glm::max(glm::ivec2(1), glm::ivec2(glm::ceil((max - min) / cell_)))),
        points_(static_cast<std::size_t>(cells_.x + 2 * margin) * static_cast<std::size_t>(cells_.y + 2 * margin),
                glm::vec2(std::numeric_limits<float>::infinity())) {}

  glm::ivec2 cells() const { return cells_; }
  glm::vec2 corner(const glm::ivec2& cell) const { return min_ + glm::vec2(cell) * cell_; }
  void put(const glm::vec2& p) { points_[index(cell_of(p))] = p; }

  // No point within the radius of p: the 5×5 cells around its own, nearest rows first.
  bool far_enough(const glm::vec2& p) const {
    const std::size_t row = static_cast<std::size_t>(cells_.x + 2 * margin);
    const glm::vec2* centre = points_.data() + index(cell_of(p));
    for (std::ptrdiff_t dy : {0, -1, 1, -2, 2}) {
      const glm::vec2* cells = centre + dy * static_cast<std::ptrdiff_t>(row);
      for (std::ptrdiff_t dx = -margin; dx <= margin; ++dx) {
        const glm::vec2 d = cells[dx] - p;
        if (glm::dot(d, d) < radius2_) return false;
      }
    }
    return true;
  }

 private:
  static constexpr int margin = 2;

  glm::ivec2 cell_of(const glm::vec2& p) const { return glm::min(glm::ivec2((p - min_) / cell_), cells_ - 1); }
  std::size_t index(const glm::ivec2& c) const {
    return static_cast<std::size_t>(c.y + margin) * static_cast<std::size_t>(cells_.x + 2 * margin) +
           static_cast<std::size_t>(c.x + margin);
  }

  glm::vec2 min_;
  float cell_, radius2_;
  glm::ivec2 cells_;
  std::vector<glm::vec2> points_;
};

// Bridson's growth inside the rectangle [lo, hi), against the points already in the grid: a first
// point where one fits, then from a random active point `attempts` candidates in the annulus
// r..2r at evenly turned angles; a point none of whose candidates fit retires.
std::vector<glm::vec2> fill_tile(PointGrid& grid, const glm::vec2& lo, const glm::vec2& hi, float radius, int attempts,
                                 std::uint64_t seed) {
  Random rng(seed);
  std::vector<glm::vec2> points, active;
  auto inside = [&](const glm::vec2& p) { return p.x >= lo.x && p.y >= lo.y && p.x < hi.x && p.y < hi.y; };
  auto add = [&](const glm::vec2& p) {
    grid.put(p);
    active.push_back(p);
    points.push_back(p);
  };
  for (int k = 0; k < 64; ++k) {  // the tile's neighbours may already cover its edges
    const glm::vec2 p(rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y));
    if (inside(p) && grid.far_enough(p)) {
      add(p);
      break;
    }
  }
  const float step = glm::two_pi<float>() / static_cast<float>(attempts);
  const glm::vec2 turn(std::cos(step), std::sin(step));
  while (!active.empty()) {
    const std::size_t pick = rng.below(static_cast<std::uint32_t>(active.size()));
    const glm::vec2 center = active[pick];
    const float angle = rng.uniform(0.0f, glm::two_pi<float>());
    glm::vec2 direction(std::cos(angle), std::sin(angle));
    bool placed = false;
    for (int k = 0; k < attempts && !placed; ++k) {
      const glm::vec2 p = center + radius * std::sqrt(rng.uniform(1.0f, 4.0f)) * direction;  // uniform over the annulus
      direction = glm::vec2(direction.x * turn.x - direction.y * turn.y, direction.x * turn.y + direction.y * turn.x);
      if (!inside(p) || !grid.far_enough(p)) continue;
      add(p);
      placed = true;
    }
    if (!placed) {
      active[pick] = active.back();
      active.pop_back();
    }
  }
  return points;
}

}  // namespace

std::vector<glm::vec2> poisson_disk(const glm::vec2& min, const glm::vec2& max, float radius, Random& rng, int attempts,
                                    int threads) {
  PointGrid grid(min, max, radius);
  const glm::ivec2 tiles = (grid.cells() + tile_cells - 1) / tile_cells;
  const std::uint64_t tile_seeds = rng.next();
  std::vector<std::vector<glm::vec2>> tile_points(static_cast<std::size_t>(tiles.x) * static_cast<std::size_t>(tiles.y));
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int phase = 0; phase < 4; ++phase) {
    std::vector<int> todo;
    for (int ty = phase >> 1; ty < tiles.y; ty += 2) {
      for (int tx = phase & 1; tx < tiles.x; tx += 2) todo.push_back(ty * tiles.x + tx);
    }
    std::atomic<std::size_t> next{0};
    std::mutex failing;
    std::exception_ptr failure;  // the first a thread met (out of memory), thrown after the join
    auto work = [&] {
      try {
        for (std::size_t i = next++; i < todo.size(); i = next++) {
          const int t = todo[i];
          const glm::ivec2 tile(t % tiles.x, t / tiles.x);
          const glm::vec2 lo = grid.corner(tile * tile_cells);
          const glm::vec2 hi = glm::min(max, grid.corner((tile + 1) * tile_cells));
          tile_points[static_cast<std::size_t>(t)] = fill_tile(grid, lo, hi, radius, attempts, derive_seed(tile_seeds, static_cast<std::uint64_t>(t)));
        }
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failing);
        if (!failure) failure = std::current_exception();
        next = todo.size();
      }
    };
    std::vector<std::thread> helpers;
    for (int k = 1; k < std::min<int>(threads, static_cast<int>(todo.size())); ++k) helpers.emplace_back(work);
    work();
    for (std::thread& helper : helpers) helper.join();
    if (failure) std::rethrow_exception(failure);
  }
  std::vector<glm::vec2> points;
  for (const std::vector<glm::vec2>& some : tile_points) points.insert(points.end(), some.begin(), some.end());
  return points;
}

}  // namespace pointgen
