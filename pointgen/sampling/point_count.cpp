#include "pointgen/sampling/point_count.hpp"

#include <algorithm>

namespace pointgen {

float points_needed(const PointDensity& density, float area, float depth, float distance) {
  const float z = std::max(depth, 1e-3f);
  const float d = std::max(distance, z);  // callers' rounding aside, depth <= distance
  return density.k * density.pixels_per_radian * density.pixels_per_radian * area * d / (2.0f * z * z * z);
}

}  // namespace pointgen
