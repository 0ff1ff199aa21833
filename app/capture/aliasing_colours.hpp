#pragma once
#include "app/render/image.hpp"

#include <array>
#include <cstdint>

namespace ecoview {

// The colours of the `aliasing` AOV: the aliasing factor (the size, in screen pixels, of a shadow
// map texel on the surface seen) on a log scale from blue (1/8 of a pixel) through green (1) to
// red (8 and more); black where no surface was drawn or there is no shadow map (factor 0).
std::array<std::uint8_t, 3> aliasing_colour(float factor);

// The heat map of an aliasing image, RGB.
Image8 aliasing_heat_map(const Image<float>& aliasing);

// A bar of the colours from 1/8 to 8 with ticks labelled 1/8, 1/4, 1/2, 1, 2, 4, 8 (white on
// dark grey), to look at beside a heat map.
Image8 aliasing_legend();

}  // namespace ecoview
