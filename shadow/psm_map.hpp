#pragma once
#include "shadow/shadow_inputs.hpp"
#include "shadow/shadow_setup.hpp"

namespace shadow {

// The perspective shadow map (Stamminger and Drettakis 2002): the shadow map rendered in the camera's post-perspective
// space, where what is near the eye is large, so the map spends its texels where the eye looks
// closely.
//   near plane pushed → focus bodies → virtual camera → light in post-perspective space → fit,
// moving the virtual camera further back while the fit fails (each step nearer a uniform map),
// and the focused uniform map if it never holds (a point light among the receivers) or when the
// receivers spread so wide around a point light that the uniform map takes a cube.
// The near plane is pushed to ShadowInputs::nearest_visible (Sect. 6).
ShadowSetup perspective_shadow_map(const ShadowInputs& in);

}  // namespace shadow
