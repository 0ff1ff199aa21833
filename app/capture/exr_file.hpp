#pragma once
#include "app/render/image.hpp"

#include <string>

namespace ecoview {

// A one-channel image as an OpenEXR file in memory: 32-bit float samples in the channel named
// `channel` (Z for depth, Y for a gray value, as OpenEXR names them), ZIP-compressed (lossless),
// rows from the top.
std::string encode_exr(const Image<float>& image, const char* channel);

}  // namespace ecoview
