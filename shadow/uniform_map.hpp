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

// The uniform map of all the scene the light reaches, its rows along the world's −z: it depends
// on the light and the scene alone, not on the camera, so the pages of a virtual map over it
// (--method adaptive) stay valid while the camera moves.
ShadowSetup lit_scene_map(const ShadowInputs& in);

}  // namespace shadow
