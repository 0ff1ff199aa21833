#pragma once
#include <algorithm>
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

// An image from rows that go up from the bottom, as OpenGL returns them.
template <class Sample>
Image<Sample> from_bottom_up(int width, int height, int channels, const std::vector<Sample>& bottom_up) {
  Image<Sample> image{width, height, channels, std::vector<Sample>(bottom_up.size())};
  const std::size_t row = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
  for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y) {
    std::copy_n(bottom_up.begin() + static_cast<std::ptrdiff_t>(row * (static_cast<std::size_t>(height) - 1 - y)), row,
                image.samples.begin() + static_cast<std::ptrdiff_t>(row * y));
  }
  return image;
}

using Image8 = Image<std::uint8_t>;
using Image16 = Image<std::uint16_t>;

}  // namespace ecoview
