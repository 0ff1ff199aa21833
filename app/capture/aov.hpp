#pragma once
#include "app/render/frame_pass.hpp"

#include <string>
#include <vector>

namespace ecoview {

// The images `capture` writes per frame (DESIGN.md): color (sRGB), shadow (255 × light
// visibility, 255 where no surface), depth (16-bit linear view depth).
enum class Aov { color, shadow, depth };

std::string aov_name(Aov aov);
// Parses a comma-separated --aov list; throws InputError on an unknown name or an empty list.
std::vector<Aov> parse_aov_list(const std::string& list);

// The AOV of the last rendered frame as a PNG file. Depth is stored as
// round(65534 × view depth / far), 65535 where no surface was drawn.
std::string encode_aov(Aov aov, const FramePass& frame, float far);

}  // namespace ecoview
