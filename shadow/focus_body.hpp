#pragma once
#include "shadow/camera.hpp"
#include "shadow/convex_body.hpp"
#include "shadow/light.hpp"

#include <array>
#include <vector>

// The bodies a shadow map must cover (PSM paper, Sect. 4.1): the receivers V ∩ S ∩ L the camera
// can see, and H = M ∩ S ∩ L, every point that can cast a shadow onto them, where V is the view
// frustum, S the scene bounds, L the light's frustum and M the convex hull of V and the light.
namespace shadow {

// World-space corners of the view frustum, indexed like Box::corner over the NDC cube.
std::array<glm::vec3, 8> frustum_corners(const glm::mat4& view_projection);

// Planes bounding the light's frustum L: a spot light's square pyramid around its cone; none for
// directional and point lights, whose L is all of space.
std::vector<Plane> light_frustum_planes(const Light& light);

// Planes bounding M, the convex hull of `body` and the light (for a directional light, `body`
// swept towards the light without end).
std::vector<Plane> hull_with_light(const ConvexBody& body, const Light& light);

struct FocusBodies {
  ConvexBody receivers;  // V ∩ S ∩ L
  ConvexBody casters;    // H = M ∩ S ∩ L; contains the receivers
};

FocusBodies focus_bodies(const glm::mat4& view_projection, const Light& light, const Box& scene);

// The focus bodies, never empty, for maps that must always cover something: where the camera sees
// none of the scene (`bodies` empty), the part of the scene the light reaches; where the light
// reaches none of it, the whole scene.
FocusBodies or_scene(FocusBodies bodies, const Light& light, const Box& scene);

}  // namespace shadow
