#pragma once
#include <cmath>

namespace pointgen {

// An sRGB-encoded value in 0..1 as linear light (IEC 61966-2-1).
inline float srgb_to_linear(float srgb) {
  return srgb <= 0.04045f ? srgb / 12.92f : std::pow((srgb + 0.055f) / 1.055f, 2.4f);
}

}  // namespace pointgen
