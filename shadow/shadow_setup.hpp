#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace shadow {

// A paraboloid map (Brabec et al. 2002) maps a light-space point q by the direction
// d = q / |q|, in place of a projection matrix: the stereographic projection around the axis -z,
//   map xy = d.xy / (1 - d.z) / zoom,   depth = 2 |q| / range - 1,
// puts the cone of half-angle 2 atan(zoom) into the unit disc (zoom 1: the hemisphere), with
// depth linear in the distance from the light.
struct Paraboloid {
  float zoom = 1.0f;
  float range = 1.0f;  // metres from the light at depth 1
};

// One shadow-map view: world → light space → light clip space. Points it must cover map into the
// clip cube [-1, 1]^3. For a perspective shadow map `view` passes through the camera's
// post-perspective space and is projective. A paraboloid view has a `paraboloid` and no
// projection (identity).
struct ShadowView {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  std::optional<Paraboloid> paraboloid;

  ShadowView() = default;
  ShadowView(const glm::mat4& view, const glm::mat4& projection) : view(view), projection(projection) {}
  ShadowView(const glm::mat4& view, const Paraboloid& paraboloid) : view(view), paraboloid(paraboloid) {}

  glm::mat4 view_projection() const { return projection * view; }
  // view_projection() of a projective view; none for a paraboloid view, which no matrix projects.
  std::optional<glm::mat4> clip_matrix() const {
    if (paraboloid) return std::nullopt;
    return view_projection();
  }
  // (zoom, range) as the shaders take them; zoom 0 for a projective view.
  glm::vec2 paraboloid_parameters() const {
    return paraboloid ? glm::vec2(paraboloid->zoom, paraboloid->range) : glm::vec2(0.0f);
  }
  // The clip coordinates of a world point, for either kind of view. A paraboloid view returns them
  // homogeneous with w = 1 - d.z, so w <= 0 only straight behind its axis.
  glm::vec4 clip(const glm::vec3& world) const {
    if (!paraboloid) return view_projection() * glm::vec4(world, 1.0f);
    const glm::vec3 q(view * glm::vec4(world, 1.0f));
    const float distance = glm::length(q);
    const glm::vec3 d = distance > 0.0f ? q / distance : glm::vec3(0.0f, 0.0f, -1.0f);
    const float w = 1.0f - d.z;
    return {d.x / paraboloid->zoom, d.y / paraboloid->zoom, (2.0f * distance / paraboloid->range - 1.0f) * w, w};
  }
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

// Whether a view's matrices and paraboloid are finite numbers, the paraboloid's positive.
inline bool finite(const ShadowView& v) {
  if (!finite(v.view) || !finite(v.projection)) return false;
  return !v.paraboloid || (std::isfinite(v.paraboloid->zoom) && v.paraboloid->zoom > 0.0f &&
                           std::isfinite(v.paraboloid->range) && v.paraboloid->range > 0.0f);
}

// How a surface point picks the view whose map holds its shadow.
enum class ViewSelection {
  single,      // one map
  cube_faces,  // six maps around a point light, by the major axis of (point - light):
               // +x, -x, +y, -y, +z, -z
  first_containing,  // cascades: the first map whose box holds the point (in depth, and across
                     // two texels in from its edge, for the filter), else the last
  hemispheres,  // dual paraboloids: the first in front of its light view (light-space z <= 0),
                // else the second
  screen_mask,  // no map (shadow volumes): the renderer's per-pixel mask of lit surfaces
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
