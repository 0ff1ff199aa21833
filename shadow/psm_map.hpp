#pragma once
#include "shadow/box.hpp"
#include "shadow/camera.hpp"
#include "shadow/light.hpp"
#include "shadow/shadow_setup.hpp"

namespace shadow {

// The perspective shadow map (Stamminger and Drettakis 2002): the shadow map rendered in the camera's post-perspective
// space, where what is near the eye is large, so the map spends its texels where the eye looks
// closely.
//   near plane pushed → focus bodies → virtual camera → light in post-perspective space → fit,
// moving the virtual camera further back while the fit fails (each step nearer a uniform map),
// and the focused uniform map if it never holds (a point light among the receivers) or when the
// receivers spread so wide around a point light that the uniform map takes a cube.
// `nearest_visible` is the depth of the nearest surface the camera saw last frame (Sect. 6), 0
// when unknown.
ShadowSetup perspective_shadow_map(const Camera& camera, float aspect, const Light& light, const Box& scene,
                                   int map_size, float nearest_visible = 0.0f);

}  // namespace shadow
