#include "app/capture/aov.hpp"

#include "app/capture/aliasing_colours.hpp"
#include "app/capture/exr_file.hpp"
#include "app/capture/png.hpp"
#include "app/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <sstream>

namespace ecoview {

std::string aov_name(Aov aov) {
  switch (aov) {
    case Aov::color: return "color";
    case Aov::shadow: return "shadow";
    case Aov::depth: return "depth";
    case Aov::aliasing: return "aliasing";
    case Aov::shadowmap: return "shadowmap";
    case Aov::reference: return "reference";
  }
  return "?";
}

std::vector<Aov> parse_aov_list(const std::string& list) {
  std::vector<Aov> aovs;
  std::stringstream stream(list);
  std::string name;
  if (list == "none") return aovs;
  if (!list.empty() && list.back() == ',') throw InputError("--aov: empty name in '" + list + "'");
  while (std::getline(stream, name, ',')) {
    const Aov all[] = {Aov::color, Aov::shadow, Aov::depth, Aov::aliasing, Aov::shadowmap, Aov::reference};
    const auto* found = std::find_if(std::begin(all), std::end(all), [&](Aov a) { return aov_name(a) == name; });
    if (found == std::end(all)) {
      throw InputError("--aov: unknown AOV '" + name + "' (available: color, shadow, depth, aliasing, shadowmap, reference; or none alone)");
    }
    if (std::find(aovs.begin(), aovs.end(), *found) == aovs.end()) aovs.push_back(*found);
  }
  if (aovs.empty()) throw InputError("--aov: empty list (available: color, shadow, depth, aliasing, shadowmap, reference)");
  return aovs;
}

AovFormat parse_aov_format(const std::string& name) {
  if (name == "png") return AovFormat::png;
  if (name == "exr") return AovFormat::exr;
  throw InputError("--aov-format: expected png or exr, got '" + name + "'");
}

bool has_float_form(Aov aov) { return aov == Aov::depth || aov == Aov::shadow || aov == Aov::reference; }

namespace {

bool as_exr(Aov aov, AovFormat format) { return format == AovFormat::exr && has_float_form(aov); }

}  // namespace

std::filesystem::path aov_file(const std::filesystem::path& out, Aov aov, int frame, AovFormat format) {
  char name[64];
  std::snprintf(name, sizeof name, "%s_%05d.%s", aov_name(aov).c_str(), frame, as_exr(aov, format) ? "exr" : "png");
  return out / name;
}

namespace {

// Depths 0..1 as gray 0..255.
Image8 depth_gray(const Image<float>& depth) {
  Image8 image{depth.width, depth.height, 1, {}};
  image.samples.reserve(depth.samples.size());
  for (float d : depth.samples) image.samples.push_back(static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(d, 0.0f, 1.0f))));
  return image;
}

// Visibility 0..255 as 0..1. The renderer keeps it in 8 bits (an R8 target; the reference traces
// lit or not), so these are its own values, in float.
Image<float> visibility_fraction(const Image8& visibility) {
  Image<float> fraction{visibility.width, visibility.height, 1, {}};
  fraction.samples.reserve(visibility.samples.size());
  for (std::uint8_t v : visibility.samples) fraction.samples.push_back(static_cast<float>(v) / 255.0f);
  return fraction;
}

// Linear view depth in metres, +inf where no surface was drawn (negative in the frame's depth).
Image<float> depth_metres(Image<float> depth) {
  for (float& d : depth.samples) {
    if (d < 0.0f) d = std::numeric_limits<float>::infinity();
  }
  return depth;
}

std::string encode_float_aov(Aov aov, Renderer& renderer) {
  switch (aov) {
    case Aov::depth: return encode_exr(depth_metres(renderer.frame().read_depth()), "Z");
    case Aov::shadow: return encode_exr(visibility_fraction(renderer.frame().read_visibility()), "Y");
    case Aov::reference: return encode_exr(visibility_fraction(renderer.exact_visibility()), "Y");
    default: throw std::logic_error("encode_float_aov: " + aov_name(aov) + " has no float form");
  }
}

}  // namespace

std::string encode_aov(Aov aov, Renderer& renderer, float far, AovFormat format) {
  if (as_exr(aov, format)) return encode_float_aov(aov, renderer);
  const FramePass& frame = renderer.frame();
  switch (aov) {
    case Aov::color: return encode_png(frame.read_color());
    case Aov::shadow: return encode_png(frame.read_visibility());
    case Aov::depth: {
      const Image<float> depth = frame.read_depth();
      Image16 encoded{depth.width, depth.height, 1, {}};
      encoded.samples.reserve(depth.samples.size());
      for (float d : depth.samples) {
        encoded.samples.push_back(d < 0.0f ? 65535
                                           : static_cast<std::uint16_t>(std::lround(std::clamp(d / far, 0.0f, 1.0f) * 65534.0f)));
      }
      return encode_png(encoded);
    }
    case Aov::aliasing: return encode_png(aliasing_heat_map(frame.read_aliasing()));
    case Aov::shadowmap: return encode_png(depth_gray(renderer.shadow_map().read_layer(0)));
    case Aov::reference: return encode_png(renderer.exact_visibility());
  }
  return {};
}

}  // namespace ecoview
