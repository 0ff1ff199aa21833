#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <optional>

namespace pointgen {

// A rectangle in normalized device coordinates.
struct ScreenRect {
  glm::vec2 min, max;
  float area() const { return (max.x - min.x) * (max.y - min.y); }
  // Whether any of it lies on screen.
  bool on_screen() const { return max.x >= -1.0f && min.x <= 1.0f && max.y >= -1.0f && min.y <= 1.0f; }
};

// The rectangle holding a box (its centre and half sizes in the frame that `to_clip` maps to clip
// space), or none when part of it lies behind the eye.
inline std::optional<ScreenRect> project_box(const glm::mat4& to_clip, const glm::vec3& center, const glm::vec3& half_size) {
  // The corners in clip space: the centre's image plus or minus the images of the half axes.
  const glm::vec4 middle = to_clip * glm::vec4(center, 1.0f);
  const glm::vec4 x = to_clip[0] * half_size.x, y = to_clip[1] * half_size.y, z = to_clip[2] * half_size.z;
  ScreenRect rect{glm::vec2(INFINITY), glm::vec2(-INFINITY)};
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 clip = middle + ((i & 1) ? x : -x) + ((i & 2) ? y : -y) + ((i & 4) ? z : -z);
    if (!(clip.w > 1e-6f)) return std::nullopt;
    rect.min = glm::min(rect.min, glm::vec2(clip) / clip.w);
    rect.max = glm::max(rect.max, glm::vec2(clip) / clip.w);
  }
  return rect;
}

}  // namespace pointgen
