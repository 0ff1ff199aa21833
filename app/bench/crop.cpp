#include "app/bench/crop.hpp"

#include <algorithm>
#include <vector>

namespace ecoview {
namespace {

bool lit(const Image8& visibility, int x, int y) { return visibility.at(x, y) > 127; }

// 1 where a pixel's lit state differs from its right or lower neighbour's.
std::vector<int> shadow_edges(const Image8& visibility) {
  std::vector<int> edges(static_cast<std::size_t>(visibility.width) * static_cast<std::size_t>(visibility.height), 0);
  for (int y = 0; y + 1 < visibility.height; ++y) {
    for (int x = 0; x + 1 < visibility.width; ++x) {
      const bool here = lit(visibility, x, y);
      edges[static_cast<std::size_t>(y) * static_cast<std::size_t>(visibility.width) + static_cast<std::size_t>(x)] =
          here != lit(visibility, x + 1, y) || here != lit(visibility, x, y + 1);
    }
  }
  return edges;
}

int count_in(const std::vector<int>& edges, int image_width, const PixelRect& rect) {
  int count = 0;
  for (int y = rect.y; y < rect.y + rect.height; ++y) {
    for (int x = rect.x; x < rect.x + rect.width; ++x) count += edges[static_cast<std::size_t>(y) * static_cast<std::size_t>(image_width) + static_cast<std::size_t>(x)];
  }
  return count;
}

}  // namespace

PixelRect busiest_shadow_edges(const Image8& visibility, int width, int height) {
  const std::vector<int> edges = shadow_edges(visibility);
  const int step_x = std::max(1, visibility.width / 8), step_y = std::max(1, visibility.height / 8);
  PixelRect busiest{0, 0, width, height};
  int most = -1;
  for (int y = 0; y + height <= visibility.height; y += step_y) {
    for (int x = 0; x + width <= visibility.width; x += step_x) {
      const int count = count_in(edges, visibility.width, {x, y, width, height});
      if (count > most) busiest = {x, y, width, height}, most = count;
    }
  }
  return busiest;
}

Image8 magnified_crop(const Image8& image, const PixelRect& rect, int factor) {
  Image8 crop{rect.width * factor, rect.height * factor, image.channels, {}};
  crop.samples.reserve(static_cast<std::size_t>(crop.width) * static_cast<std::size_t>(crop.height) *
                       static_cast<std::size_t>(crop.channels));
  for (int y = 0; y < crop.height; ++y) {
    for (int x = 0; x < crop.width; ++x) {
      for (int c = 0; c < image.channels; ++c) crop.samples.push_back(image.at(rect.x + x / factor, rect.y + y / factor, c));
    }
  }
  return crop;
}

}  // namespace ecoview
