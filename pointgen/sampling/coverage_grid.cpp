#include "pointgen/sampling/coverage_grid.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace pointgen {
namespace {

// Points are projected this many at a time, in a loop the compiler turns into vector code: most
// points a frame samples come through the grid (a near plant drawn as polygons covers its cells
// with a sample each).
constexpr std::size_t projected_block = 8;

struct ProjectedBlock {
  std::array<bool, projected_block> kept;              // as the splatting shader (point_walk.glsl)
  std::array<float, projected_block> corner_x, corner_y;  // the splat's corner cell, before floor
};

// Drops what the splatting shader drops (behind the eye, outside the view, nearer or farther than
// its depth range) and finds the splat's corner as it does. m * vec4(p, 1) summed in glm's order,
// so that every bit agrees with glm's.
ProjectedBlock project_block(const glm::vec3* p, const glm::mat4& m, glm::vec2 size, float half_splat) {
  ProjectedBlock out;
  for (std::size_t j = 0; j < projected_block; ++j) {
    const auto row = [&](int r) { return (m[0][r] * p[j].x + m[1][r] * p[j].y) + (m[2][r] * p[j].z + m[3][r]); };
    const float w = row(3);
    const float x = row(0) / w, y = row(1) / w, z = row(2) / w;
    out.kept[j] = (w > 1e-6f) & (std::abs(x) <= 1.0f) & (std::abs(y) <= 1.0f) & (std::abs(z) <= 1.0f);
    out.corner_x[j] = (x * 0.5f + 0.5f) * size.x - half_splat;
    out.corner_y[j] = (y * 0.5f + 0.5f) * size.y - half_splat;
  }
  return out;
}

}  // namespace

CoverageGrid::CoverageGrid(const glm::mat4& view_projection, glm::ivec2 cells, int splat)
    : view_projection_(view_projection),
      cells_(glm::max(cells, glm::ivec2(1))),
      tiles_((cells_ + tile_cells - 1) / tile_cells),
      splat_(std::max(splat, 1)),
      covered_(static_cast<std::size_t>(tiles_.x) * tiles_.y, 0),
      cell_share_(covered_.size()) {
  for (int ty = 0; ty < tiles_.y; ++ty) {
    for (int tx = 0; tx < tiles_.x; ++tx) {
      const int w = std::min(tile_cells, cells_.x - tx * tile_cells), h = std::min(tile_cells, cells_.y - ty * tile_cells);
      cell_share_[static_cast<std::size_t>(ty) * tiles_.x + tx] = 1.0f / static_cast<float>(w * h);
    }
  }
}

std::optional<CoverageGrid::Rect> CoverageGrid::project(const glm::vec3& center, const glm::vec3& half_size,
                                                        const glm::mat4& transform) const {
  return project_box(view_projection_ * transform, center, half_size);
}

float CoverageGrid::ndc_area_per_square_metre(const glm::vec3& point) const {
  const glm::mat4& m = view_projection_;
  const float w = (m * glm::vec4(point, 1.0f)).w;
  const glm::vec3 row_x(m[0][0], m[1][0], m[2][0]), row_y(m[0][1], m[1][1], m[2][1]);
  return glm::length(row_x) * glm::length(row_y) / (w * w);
}

template <class Visit>
void CoverageGrid::for_squares(const Rect& rect, int cells_per_side, glm::ivec2 squares, Visit visit) const {
  // Square coordinates: [0, squares) across the screen's [-1, 1] (the last may reach past it).
  const glm::vec2 size = glm::vec2(cells_) / static_cast<float>(cells_per_side);
  const glm::vec2 lo = glm::clamp((rect.min + 1.0f) * 0.5f * size, glm::vec2(0.0f), size);
  const glm::vec2 hi = glm::clamp((rect.max + 1.0f) * 0.5f * size, glm::vec2(0.0f), size);
  if (!(hi.x > lo.x && hi.y > lo.y)) return;
  const int x1 = static_cast<int>(lo.x), y1 = static_cast<int>(lo.y);
  const int x2 = std::min(static_cast<int>(std::ceil(hi.x)), squares.x) - 1, y2 = std::min(static_cast<int>(std::ceil(hi.y)), squares.y) - 1;
  for (int y = y1; y <= y2; ++y) {
    const float fy = std::min(hi.y, y + 1.0f) - std::max(lo.y, static_cast<float>(y));
    for (int x = x1; x <= x2; ++x) {
      const float fx = std::min(hi.x, x + 1.0f) - std::max(lo.x, static_cast<float>(x));
      visit(static_cast<std::size_t>(y) * squares.x + x, fx * fy);
    }
  }
}

float CoverageGrid::transmittance(const Rect& rect) const {
  float sum = 0.0f, weight = 0.0f;
  // Small rectangles cell by cell, so that a small object in a tile that is mostly covered
  // counts as hidden where it is; large ones by tiles.
  if (cells_in(rect) <= static_cast<float>(max_cells_read)) {
    for_squares(rect, 1, cells_, [&](std::size_t cell, float fraction) {
      const int x = static_cast<int>(cell % static_cast<std::size_t>(cells_.x)), y = static_cast<int>(cell / static_cast<std::size_t>(cells_.x));
      sum += (covered_[tile_of(x, y)] >> bit_of(x, y) & 1u) ? 0.0f : fraction;
      weight += fraction;
    });
  } else {
    for_squares(rect, tile_cells, tiles_, [&](std::size_t tile, float fraction) {
      sum += fraction * (1.0f - static_cast<float>(std::popcount(covered_[tile])) * cell_share_[tile]);
      weight += fraction;
    });
  }
  return weight > 0.0f ? sum / weight : 1.0f;
}

void CoverageGrid::cover_splats(std::span<const glm::vec3> points, const glm::mat4& transform, int splat) {
  const glm::mat4 m = view_projection_ * transform;
  const glm::vec2 size(cells_);
  const float half_splat = 0.5f * static_cast<float>(splat - 1);
  std::array<glm::vec3, projected_block> tail;
  for (std::size_t first = 0; first < points.size(); first += projected_block) {
    const std::size_t count = std::min(projected_block, points.size() - first);
    const glm::vec3* block = points.data() + first;
    if (count < projected_block) {  // the last, padded with its last point
      std::fill(std::copy(block, block + count, tail.begin()), tail.end(), block[count - 1]);
      block = tail.data();
    }
    const ProjectedBlock projected = project_block(block, m, size, half_splat);
    for (std::size_t j = 0; j < count; ++j) {
      if (!projected.kept[j]) continue;
      const int x0 = static_cast<int>(std::floor(projected.corner_x[j])), y0 = static_cast<int>(std::floor(projected.corner_y[j]));
      for (int y = std::max(y0, 0); y < std::min(y0 + splat, cells_.y); ++y) {
        for (int x = std::max(x0, 0); x < std::min(x0 + splat, cells_.x); ++x) cover_cell(x, y);
      }
    }
  }
}

void CoverageGrid::cover(std::span<const glm::vec3> points, const glm::mat4& transform) {
  cover_splats(points, transform, splat_);
}

void CoverageGrid::cover_surface(std::span<const glm::vec3> points, const glm::mat4& transform) {
  cover_splats(points, transform, 1);
}

void CoverageGrid::cover_cell(int x, int y) { covered_[tile_of(x, y)] |= std::uint64_t{1} << bit_of(x, y); }

}  // namespace pointgen
