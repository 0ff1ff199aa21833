#pragma once
#include "shadow/focus_body.hpp"
#include "shadow/shadow_setup.hpp"

#include <optional>

namespace shadow {

// Widest half-angle of receivers around a light served by one perspective map; beyond it texels
// at the map's rim grow too large.
constexpr float max_single_map_half_angle_deg = 60.0f;

// A cone from an apex around points: its axis and the cosine of its half-angle (-1 when the
// points surround the apex).
struct Cone {
  glm::vec3 axis;
  float cos_half_angle;
};
Cone cone_around(const glm::vec3& apex, const std::vector<glm::vec3>& points);

// Up vector for a light view along `axis`: the camera's view direction `forward` (in the same
// space) where it is not parallel, so the map's rows follow the view.
glm::vec3 light_up(const glm::vec3& axis, const glm::vec3& forward);

// The light's view of the focus bodies as one projective map, for a light at a finite point, at
// infinity, or beyond infinity (an inverted light, whose rays converge on it: Stamminger and Drettakis 2002, Sect. 3),
// with no switch between the cases. `light` is the homogeneous point the light shines from:
// (position, 1) for a point light, (-direction, 0) for a directional one, any w in post-perspective
// space. The map's axis runs through the receivers' centre the way the light travels there, and
// depth grows along the rays in every case, so the first hit along a ray is always the nearest
// depth: an inverted light needs no reversed depth test. `forward` orients the map's rows.
//
// None when no single map can hold the receivers: the light among them, or seeing them wider
// than max_single_map_half_angle_deg from its axis.
std::optional<ShadowView> fit_light_view(const glm::vec4& light, const FocusBodies& bodies, const glm::vec3& forward);

}  // namespace shadow
