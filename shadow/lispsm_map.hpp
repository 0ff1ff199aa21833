#pragma once
#include "shadow/shadow_inputs.hpp"
#include "shadow/shadow_setup.hpp"

namespace shadow {

// Light space perspective shadow map (Wimmer, Scherzer, Purgathofer 2004): a perspective warp
// whose axis is the view direction made perpendicular to the light, so the light stays
// directional in the warped space and the map is fitted there orthographically.
//   focus bodies → warp axis → warp centre at Wimmer's n_opt → fit in the warped space.
// The warp fades to none as the view turns parallel to the light. Directional lights only: point
// and spot lights get the focused uniform map.
ShadowSetup light_space_perspective_map(const ShadowInputs& in);

}  // namespace shadow
