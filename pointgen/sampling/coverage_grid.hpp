#pragma once
#include "pointgen/sampling/screen_rect.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace pointgen {

// Which parts of a view are already covered, as objects are added front to back: the sampler's
// occlusion model (docs/point_density.md, "Occlusion"). The view is cut into cells, one per pixel,
// each covered once a point's splat covers it; a tile of 8 x 8 cells has a transmittance, the
// fraction of its cells through which objects behind can still be seen.
class CoverageGrid {
 public:
  using Rect = ScreenRect;

  static constexpr int tile_cells = 8;  // per side of a tile

  // `cells` across the view (its pixels); each point covers `splat` x `splat` of them around its
  // position, as the splatting shaders do.
  CoverageGrid(const glm::mat4& view_projection, glm::ivec2 cells, int splat = 1);

  // The screen rectangle holding a box (its centre and half sizes in a frame that `transform`
  // places), or none when part of it lies behind the eye.
  std::optional<Rect> project(const glm::vec3& center, const glm::vec3& half_size, const glm::mat4& transform) const;
  // Square NDC units that one square metre facing the view covers at `point`.
  float ndc_area_per_square_metre(const glm::vec3& point) const;
  // How many cells `rect` spans, on screen or not.
  float cells_in(const Rect& rect) const { return 0.25f * rect.area() * static_cast<float>(cells_.x) * static_cast<float>(cells_.y); }
  // Mean transmittance over the part of `rect` on screen (1 where nothing covers it yet).
  float transmittance(const Rect& rect) const;
  // Covers the cells of the splats of `points` (in their object's frame, placed by `transform`).
  void cover(std::span<const glm::vec3> points, const glm::mat4& transform);
  // Covers the cells that `points` fall in: samples of a surface drawn as polygons, which cover
  // no more than the surface itself.
  void cover_surface(std::span<const glm::vec3> points, const glm::mat4& transform);

 private:
  static constexpr int max_cells_read = 256;  // a rectangle's transmittance from its cells up to this

  void cover_cell(int x, int y);
  // Covers the `splat` x `splat` cells around each of `points`.
  void cover_splats(std::span<const glm::vec3> points, const glm::mat4& transform, int splat);
  std::size_t tile_of(int x, int y) const { return static_cast<std::size_t>(y / tile_cells) * tiles_.x + x / tile_cells; }
  static int bit_of(int x, int y) { return (y % tile_cells) * tile_cells + x % tile_cells; }
  // Calls visit(index, fraction of the square inside rect) for each square the rect overlaps, of
  // a grid of `squares` over the view, each `cells_per_side` cells wide.
  template <class Visit>
  void for_squares(const Rect& rect, int cells_per_side, glm::ivec2 squares, Visit visit) const;

  glm::mat4 view_projection_;
  glm::ivec2 cells_, tiles_;
  int splat_;
  // Per tile, a bit per cell (row by row): 64 cells in one word, so that covering a splat touches
  // one cache line, and the grid of a 2048² shadow view fits in 512 KiB.
  std::vector<std::uint64_t> covered_;
  std::vector<float> cell_share_;  // per tile: what one of its cells is of it (edge tiles are smaller)
};

}  // namespace pointgen
