#pragma once
#include "shadow/box.hpp"
#include "shadow/camera.hpp"
#include "shadow/light.hpp"
#include "shadow/plane.hpp"

#include <vector>

// Whether shadow volumes may be counted z-pass: only where the camera's near-plane rectangle lies
// in no volume, or the count starts wrong at the eye (Everitt and Kilgard 2002). A volume holds a
// point of that rectangle only if its caster lies between the point and the light, that is in the
// convex hull of the rectangle and the light.
namespace shadow {

// Planes (normals out) around the hull of the camera's near-plane rectangle and the light (for a
// directional light, the rectangle swept towards it without end), a little wider than the
// rectangle, against rounding.
std::vector<Plane> near_plane_light_hull(const Camera& camera, float aspect, const Light& light);

// Whether a box and the convex body inside the planes have a point in common.
bool meets(const std::vector<Plane>& planes, const Box& box);

}  // namespace shadow
