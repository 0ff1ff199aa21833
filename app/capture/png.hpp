#pragma once
#include "app/render/image.hpp"

#include <glm/vec2.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace ecoview {

// PNG files in memory: 8-bit gray or RGB, 16-bit gray; and colour PNGs read back (stb_image).
std::string encode_png(const Image8& image);
std::string encode_png(const Image16& image);

// A PNG file's pixels as 8-bit RGB; nothing if it is no PNG that can be read.
std::optional<Image8> read_png_rgb(const std::filesystem::path& file);
// A PNG file's width and height, from its header; nothing if it is no PNG that can be read.
std::optional<glm::ivec2> read_png_size(const std::filesystem::path& file);

}  // namespace ecoview
