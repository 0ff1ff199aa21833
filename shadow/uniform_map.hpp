#pragma once
#include "shadow/shadow_inputs.hpp"
#include "shadow/shadow_setup.hpp"

namespace shadow {

// The focused uniform shadow map: an orthographic (directional light) or perspective (point and
// spot light) view from the light, fitted to the receivers the camera sees and the casters that
// can shadow them, instead of to the whole scene.
//   receivers/casters → light view → fit the projection.
// A point light whose receivers spread wider than one perspective map covers well gets the six
// faces of a cube instead.
ShadowSetup focused_uniform_map(const ShadowInputs& in);

}  // namespace shadow
