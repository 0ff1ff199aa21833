#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace shadow {

// One shadow-map view: world → light space → light clip space. Points it must cover map into the
// clip cube [-1, 1]^3. For a perspective shadow map `view` passes through the camera's
// post-perspective space and is projective.
struct ShadowView {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};

  glm::mat4 view_projection() const { return projection * view; }
};

// Whether every entry of a matrix is a finite number.
inline bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

// How a surface point picks the view whose map holds its shadow.
enum class ViewSelection {
  single,      // one map
  cube_faces,  // six maps around a point light, by the major axis of (point - light):
               // +x, -x, +y, -y, +z, -z
  first_containing,  // cascades: the first map whose box holds the point (in depth, and across
                     // two texels in from its edge, for the filter), else the last
};

// Two texels: how far inside a cascade's square a point must be to use that cascade.
constexpr float cascade_margin_texels = 2.0f;

// What a renderer needs to draw a shadow map (one layer per view) and look it up.
struct ShadowSetup {
  std::vector<ShadowView> views;
  ViewSelection selection = ViewSelection::single;
  // What the method made of this frame, for reports: e.g. "psm: inverted light, camera moved
  // back 3.2 m", or "uniform" where a method handed the frame to the uniform map.
  std::string description = "uniform";
};

}  // namespace shadow
