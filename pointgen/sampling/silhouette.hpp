#pragma once
#include "pointgen/sampling/surface_samples.hpp"

#include <vector>

namespace pointgen {

// The mean area of a mesh's silhouette (square metres) over the directions it is mostly seen from:
// four around the vertical and one from above, each estimated from its surface samples (which
// stand for `area` square metres) on a grid over the bounds. With the surface area this gives how
// much of an object's surface is in front, and how much of what lies behind it hides.
float mean_silhouette_area(const std::vector<SurfaceSample>& samples, float area, const Bounds& bounds);

}  // namespace pointgen
