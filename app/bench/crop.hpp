#pragma once
#include "app/render/image.hpp"

namespace ecoview {

struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

// Of the rectangles width × height at steps of an eighth of the image, the one holding the most
// shadow edges of a visibility image (pixels lit on one side and shadowed on the other, of the
// right or lower neighbour): where methods' shadows differ most, which a crop should show.
PixelRect busiest_shadow_edges(const Image8& visibility, int width, int height);

// A rectangle of an image, each pixel drawn as factor × factor pixels (nearest neighbour), so that
// the report's crops show each method's stair steps and speckles as they are, not smoothed.
Image8 magnified_crop(const Image8& image, const PixelRect& rect, int factor);

}  // namespace ecoview
