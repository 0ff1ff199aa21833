#include "pointgen/sampling/receiver_mask.hpp"

#include "pointgen/sampling/screen_rect.hpp"

#include <algorithm>
#include <cmath>

namespace pointgen {
namespace {

constexpr int n = ReceiverMask::tiles_per_side;

// The tile holding an NDC coordinate, clamped to the view.
int tile_of(float ndc) { return std::clamp(static_cast<int>(std::floor((ndc * 0.5f + 0.5f) * n)), 0, n - 1); }

}  // namespace

ReceiverMask::ReceiverMask(const glm::mat4& view_projection, std::span<const glm::vec3> receivers)
    : view_projection_(view_projection), summed_((n + 1) * (n + 1), 0) {
  std::vector<int> marked(n * n, 0);
  for (const glm::vec3& p : receivers) {
    const glm::vec4 clip = view_projection * glm::vec4(p, 1.0f);
    if (!(clip.w > 1e-6f)) continue;
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    if (!(std::abs(ndc.x) <= 1.0f && std::abs(ndc.y) <= 1.0f)) continue;
    // And its neighbours: the receivers are a sample of the surface, and filtering reads the
    // texels around a receiver's own.
    const int x = tile_of(ndc.x), y = tile_of(ndc.y);
    for (int ty = std::max(y - 1, 0); ty <= std::min(y + 1, n - 1); ++ty) {
      for (int tx = std::max(x - 1, 0); tx <= std::min(x + 1, n - 1); ++tx) marked[ty * n + tx] = 1;
    }
  }
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      summed_[(y + 1) * (n + 1) + x + 1] =
          marked[y * n + x] + summed_[y * (n + 1) + x + 1] + summed_[(y + 1) * (n + 1) + x] - summed_[y * (n + 1) + x];
    }
  }
}

int ReceiverMask::marked_in(int x1, int y1, int x2, int y2) const {
  const auto at = [&](int x, int y) { return summed_[y * (n + 1) + x]; };
  return at(x2 + 1, y2 + 1) - at(x1, y2 + 1) - at(x2 + 1, y1) + at(x1, y1);
}

bool ReceiverMask::may_shadow(const glm::vec3& center, const glm::vec3& half_size, const glm::mat4& transform) const {
  const std::optional<ScreenRect> rect = project_box(view_projection_ * transform, center, half_size);
  if (!rect) return true;
  if (!rect->on_screen()) return false;
  return marked_in(tile_of(rect->min.x), tile_of(rect->min.y), tile_of(rect->max.x), tile_of(rect->max.y)) > 0;
}

}  // namespace pointgen
