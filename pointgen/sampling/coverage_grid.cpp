#include "pointgen/sampling/coverage_grid.hpp"

#include <algorithm>
#include <cmath>

namespace pointgen {

CoverageGrid::CoverageGrid(const glm::mat4& view_projection, glm::ivec2 tiles)
    : view_projection_(view_projection), tiles_(glm::max(tiles, glm::ivec2(1))), transmittance_(static_cast<std::size_t>(tiles_.x) * tiles_.y, 1.0f) {}

std::optional<CoverageGrid::Rect> CoverageGrid::project(const std::array<glm::vec3, 8>& corners) const {
  Rect rect{glm::vec2(INFINITY), glm::vec2(-INFINITY)};
  for (const glm::vec3& corner : corners) {
    const glm::vec4 clip = view_projection_ * glm::vec4(corner, 1.0f);
    if (!(clip.w > 1e-6f)) return std::nullopt;
    rect.min = glm::min(rect.min, glm::vec2(clip) / clip.w);
    rect.max = glm::max(rect.max, glm::vec2(clip) / clip.w);
  }
  return rect;
}

float CoverageGrid::ndc_area_per_square_metre(const glm::vec3& point) const {
  const glm::mat4& m = view_projection_;
  const float w = (m * glm::vec4(point, 1.0f)).w;
  const glm::vec3 row_x(m[0][0], m[1][0], m[2][0]), row_y(m[0][1], m[1][1], m[2][1]);
  return glm::length(row_x) * glm::length(row_y) / (w * w);
}

template <class Visit>
void CoverageGrid::for_tiles(const Rect& rect, Visit visit) const {
  // Tile coordinates: [0, tiles) across the screen's [-1, 1].
  const glm::vec2 size(tiles_);
  const glm::vec2 lo = glm::clamp((rect.min + 1.0f) * 0.5f * size, glm::vec2(0.0f), size);
  const glm::vec2 hi = glm::clamp((rect.max + 1.0f) * 0.5f * size, glm::vec2(0.0f), size);
  if (!(hi.x > lo.x && hi.y > lo.y)) return;
  const int x1 = static_cast<int>(lo.x), y1 = static_cast<int>(lo.y);
  const int x2 = static_cast<int>(std::ceil(hi.x)) - 1, y2 = static_cast<int>(std::ceil(hi.y)) - 1;
  for (int y = y1; y <= y2; ++y) {
    const float fy = std::min(hi.y, y + 1.0f) - std::max(lo.y, static_cast<float>(y));
    for (int x = x1; x <= x2; ++x) {
      const float fx = std::min(hi.x, x + 1.0f) - std::max(lo.x, static_cast<float>(x));
      visit(static_cast<std::size_t>(y) * tiles_.x + x, fx * fy);
    }
  }
}

float CoverageGrid::transmittance(const Rect& rect) const {
  float sum = 0.0f, weight = 0.0f;
  for_tiles(rect, [&](std::size_t tile, float fraction) {
    sum += fraction * transmittance_[tile];
    weight += fraction;
  });
  return weight > 0.0f ? sum / weight : 1.0f;
}

void CoverageGrid::cover(const Rect& rect, float opacity) {
  for_tiles(rect, [&](std::size_t tile, float fraction) { transmittance_[tile] *= 1.0f - opacity * fraction; });
}

}  // namespace pointgen
