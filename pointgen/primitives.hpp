#pragma once
#include "pointgen/triangle_mesh.hpp"

// Unit primitives; a scene object places one with its instance transform.
namespace pointgen {

// The cube [-0.5, 0.5]^3 with flat faces.
TriangleMesh unit_box();
// The sphere of radius 1 around the origin, as a UV sphere.
TriangleMesh unit_sphere(int slices = 48, int stacks = 24);
// The square [-0.5, 0.5]^2 in the XZ plane, facing +Y, split into a grid of cells so that
// per-vertex quantities stay accurate across a large ground.
TriangleMesh unit_plane(int cells = 1);

}  // namespace pointgen
