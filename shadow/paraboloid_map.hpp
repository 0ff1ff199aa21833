#pragma once
#include "shadow/shadow_inputs.hpp"
#include "shadow/shadow_setup.hpp"

#include <vector>

// Paraboloid shadow maps for point and spot lights (ShadowView::paraboloid). Directional lights
// get the focused uniform map.
namespace shadow {

// Dual-paraboloid map (Brabec et al. 2002): two hemispheres back to back around the light, along
// the world's vertical, each a few texels wider than a hemisphere so that filtering at the seam
// stays inside one map.
ShadowSetup dual_paraboloid_map(const ShadowInputs& in);

// Improved paraboloid map (Vanek et al. 2011, Sect. 3): one paraboloid turned to the axis of the cone from
// the light around the receivers and cut to that cone (zoom); where the cone is wider than a
// hemisphere (the light among the receivers), a dual map along that axis.
ShadowSetup improved_paraboloid_map(const ShadowInputs& in);

// World → clip matrices of frusta that together hold everything a paraboloid view maps into its
// unit disc (its cone; the map's corners go unused): the pyramid around the cone, or the six faces
// of a cube around the light where the cone is too wide for a pyramid. For culling the casters of
// its pass.
std::vector<glm::mat4> enclosing_frusta(const ShadowView& paraboloid_view);

}  // namespace shadow
