#pragma once
#include "app/render/renderer.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace ecoview {

// The images `capture` writes per frame (docs/capture.md): color (sRGB), shadow (255 × light
// visibility, 255 where no surface), depth (16-bit linear view depth), aliasing (heat map of the
// aliasing factor), shadowmap (the first layer of the shadow map, depth as gray, for looking at),
// reference (the exact visibility from ray tracing, encoded as shadow).
enum class Aov { color, shadow, depth, aliasing, shadowmap, reference };

// The file format of the AOVs that have a float form (has_float_form): png, or exr (32-bit float
// OpenEXR, app/capture/exr_file.hpp). The others are pictures and stay PNG.
enum class AovFormat { png, exr };

std::string aov_name(Aov aov);
// Parses a comma-separated --aov list ("none": no images); throws InputError on an unknown name or
// an empty list.
std::vector<Aov> parse_aov_list(const std::string& list);

// Parses --aov-format; throws InputError on another name.
AovFormat parse_aov_format(const std::string& name);
// Depth, shadow and reference: measures rather than pictures.
bool has_float_form(Aov aov);

// The AOV of the last rendered frame as a file. As PNG, depth is stored as
// round(65534 × view depth / far), 65535 where no surface was drawn. As EXR (`format` exr and
// has_float_form): depth is the linear view depth in metres, +inf where no surface was drawn, in
// channel Z; shadow and reference are light visibility 0..1 (1 where no surface), in channel Y. The
// aliasing heat map: app/capture/aliasing_colours.hpp.
std::string encode_aov(Aov aov, Renderer& renderer, float far, AovFormat format = AovFormat::png);
// Where capture writes an AOV of a frame: DIR/<aov>_<frame, 5 digits>.png, or .exr.
std::filesystem::path aov_file(const std::filesystem::path& out, Aov aov, int frame, AovFormat format = AovFormat::png);

}  // namespace ecoview
