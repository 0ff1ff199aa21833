#pragma once
#include "shadow/shadow_inputs.hpp"
#include "shadow/shadow_setup.hpp"

namespace shadow {

// Cascaded shadow maps for a directional light: the view depth cut into `cascades` slices by the
// practical split scheme (Zhang et al. 2006, halfway between logarithmic and uniform splits), one
// orthographic map per slice around the sphere that holds the slice, its origin snapped to whole
// texels so that shadows do not shimmer as the camera moves or turns.
//   receivers' depth range → splits → per slice: bounding sphere → light view → snap → depth.
// A surface looks up the first map whose box holds it (ViewSelection::first_containing). Point and
// spot lights get the focused uniform map.
ShadowSetup cascaded_map(const ShadowInputs& in, int cascades = 4);

}  // namespace shadow
