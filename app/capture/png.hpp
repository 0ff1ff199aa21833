#pragma once
#include "app/render/image.hpp"

#include <string>

namespace ecoview {

// PNG files in memory: 8-bit gray or RGB, 16-bit gray.
std::string encode_png(const Image8& image);
std::string encode_png(const Image16& image);

}  // namespace ecoview
