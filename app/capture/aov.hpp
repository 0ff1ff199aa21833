#pragma once
#include "app/render/renderer.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace ecoview {

// The images `capture` writes per frame (DESIGN.md): color (sRGB), shadow (255 × light
// visibility, 255 where no surface), depth (16-bit linear view depth), aliasing (heat map of the
// aliasing factor), shadowmap (the first layer of the shadow map, depth as gray, for looking at),
// reference (the exact visibility from ray tracing, encoded as shadow).
enum class Aov { color, shadow, depth, aliasing, shadowmap, reference };

std::string aov_name(Aov aov);
// Parses a comma-separated --aov list ("none": no images); throws InputError on an unknown name or
// an empty list.
std::vector<Aov> parse_aov_list(const std::string& list);

// The AOV of the last rendered frame as a PNG file. Depth is stored as
// round(65534 × view depth / far), 65535 where no surface was drawn. The aliasing heat map:
// app/capture/aliasing_colours.hpp.
std::string encode_aov(Aov aov, Renderer& renderer, float far);
// Where capture writes an AOV of a frame: DIR/<aov>_<frame, 5 digits>.png.
std::filesystem::path aov_file(const std::filesystem::path& out, Aov aov, int frame);

}  // namespace ecoview
