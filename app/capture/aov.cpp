#include "app/capture/aov.hpp"

#include "app/capture/png.hpp"
#include "app/errors.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ecoview {

std::string aov_name(Aov aov) {
  switch (aov) {
    case Aov::color: return "color";
    case Aov::shadow: return "shadow";
    case Aov::depth: return "depth";
  }
  return "?";
}

std::vector<Aov> parse_aov_list(const std::string& list) {
  std::vector<Aov> aovs;
  std::stringstream stream(list);
  std::string name;
  if (!list.empty() && list.back() == ',') throw InputError("--aov: empty name in '" + list + "'");
  while (std::getline(stream, name, ',')) {
    const Aov all[] = {Aov::color, Aov::shadow, Aov::depth};
    const auto* found = std::find_if(std::begin(all), std::end(all), [&](Aov a) { return aov_name(a) == name; });
    if (found == std::end(all)) {
      throw InputError("--aov: unknown AOV '" + name + "' (available: color, shadow, depth)");
    }
    if (std::find(aovs.begin(), aovs.end(), *found) == aovs.end()) aovs.push_back(*found);
  }
  if (aovs.empty()) throw InputError("--aov: empty list (available: color, shadow, depth)");
  return aovs;
}

std::string encode_aov(Aov aov, const FramePass& frame, float far) {
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
  }
  return {};
}

}  // namespace ecoview
