#pragma once
#include <cstdint>
#include <vector>

namespace ecoview {

// Pixels with `channels` samples each, rows from the top of the image down.
template <class Sample>
struct Image {
  int width = 0;
  int height = 0;
  int channels = 1;
  std::vector<Sample> samples;

  Sample at(int x, int y, int channel = 0) const {
    return samples[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
                       static_cast<std::size_t>(channels) + static_cast<std::size_t>(channel)];
  }
};

using Image8 = Image<std::uint8_t>;
using Image16 = Image<std::uint16_t>;

}  // namespace ecoview
