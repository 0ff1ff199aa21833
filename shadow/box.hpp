#pragma once
#include <glm/glm.hpp>

#include <array>
#include <limits>

namespace shadow {

// Axis-aligned box; empty until a point is added.
struct Box {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{std::numeric_limits<float>::lowest()};

  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  void add(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  glm::vec3 center() const { return 0.5f * (min + max); }
  // Corner i has x from max when bit 0 is set, y when bit 1, z when bit 2.
  glm::vec3 corner(int i) const {
    return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
  }
};

// The box around `box` moved by an affine transform (an instance's); empty stays empty.
inline Box transformed(const Box& box, const glm::mat4x3& transform) {
  Box out;
  if (box.empty()) return out;
  for (int i = 0; i < 8; ++i) out.add(transform * glm::vec4(box.corner(i), 1.0f));
  return out;
}

// Whether `box` lies wholly beyond one side of the clip volume of `view_projection` (world to
// clip): nothing of it can be drawn in that view.
inline bool outside_view(const Box& box, const glm::mat4& view_projection) {
  if (box.empty()) return true;
  glm::bvec3 below(true), above(true);
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 clip = view_projection * glm::vec4(box.corner(i), 1.0f);
    const glm::vec3 p(clip);
    below = below && glm::lessThan(p, glm::vec3(-clip.w));
    above = above && glm::greaterThan(p, glm::vec3(clip.w));
  }
  return glm::any(below) || glm::any(above);
}

}  // namespace shadow
