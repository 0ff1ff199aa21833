#pragma once
// Which pixels two depth images of the same plants cover (negative depth: nothing there), for
// tests that hold points against the polygons they stand for.
#include "app/render/image.hpp"

#include <cstddef>

namespace ecoview {

struct Coverage {
  std::size_t polygons = 0, points = 0, both = 0;
};

inline Coverage compare(const Image<float>& polygon_depth, const Image<float>& point_depth) {
  Coverage c;
  for (std::size_t i = 0; i < polygon_depth.samples.size(); ++i) {
    const bool a = polygon_depth.samples[i] >= 0.0f, b = point_depth.samples[i] >= 0.0f;
    c.polygons += a;
    c.points += b;
    c.both += a && b;
  }
  return c;
}

}  // namespace ecoview
