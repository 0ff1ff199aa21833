#pragma once
#include "app/render/image.hpp"

namespace ecoview {

// alias_p95 (DESIGN.md): the 95th percentile of the aliasing factor over the lit receiver pixels
// (a surface drawn, visibility >= 0.5); 0 where there are none.
double alias_p95(const Image<float>& aliasing, const Image8& visibility);

}  // namespace ecoview
