#include "app/capture/aliasing_colours.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace ecoview {
namespace {

// The legend's layout, in pixels: the bar's left end, the ticks' spacing (a doubling of the factor
// each), and where the bar, the ticks and the labels lie.
constexpr int legend_margin = 20, tick_spacing = 48, octaves = 6;
constexpr int legend_width = 2 * legend_margin + octaves * tick_spacing + 1, legend_height = 44;
constexpr int bar_top = 4, bar_bottom = 24, tick_bottom = 28, label_top = 31, glyph_scale = 2;
constexpr std::uint8_t background = 40, ink = 255;

// Glyphs of 3 × 5 pixels, a row a string, for the labels' characters.
const char* glyph(char c) {
  switch (c) {
    case '1': return ".#.##..#..#.###";
    case '2': return "##...#.#.#..###";
    case '4': return "#.##.####..#..#";
    case '8': return "####.#####.####";
    default: return "..#..#.#.#..#..";  // '/'
  }
}

void set(Image8& image, int x, int y, std::array<std::uint8_t, 3> rgb) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  std::copy(rgb.begin(), rgb.end(), image.samples.begin() + 3 * (static_cast<std::ptrdiff_t>(y) * image.width + x));
}

// `text` centred on x, its top at y.
void write(Image8& image, const std::string& text, int x, int y) {
  const int advance = 4 * glyph_scale;
  int left = x - (static_cast<int>(text.size()) * advance - glyph_scale) / 2;
  for (char c : text) {
    const char* g = glyph(c);
    for (int row = 0; row < 5; ++row) {
      for (int col = 0; col < 3; ++col) {
        if (g[row * 3 + col] != '#') continue;
        for (int s = 0; s < glyph_scale * glyph_scale; ++s) {
          set(image, left + col * glyph_scale + s % glyph_scale, y + row * glyph_scale + s / glyph_scale, {ink, ink, ink});
        }
      }
    }
    left += advance;
  }
}

}  // namespace

std::array<std::uint8_t, 3> aliasing_colour(float factor) {
  if (!(factor > 0.0f)) return {0, 0, 0};
  const float t = std::clamp((std::log2(factor) + 3.0f) / 6.0f, 0.0f, 1.0f);
  const float red = std::clamp(2.0f * t - 1.0f, 0.0f, 1.0f), blue = std::clamp(1.0f - 2.0f * t, 0.0f, 1.0f);
  auto byte = [](float c) { return static_cast<std::uint8_t>(std::lround(255.0f * c)); };
  return {byte(red), byte(1.0f - red - blue), byte(blue)};
}

Image8 aliasing_heat_map(const Image<float>& aliasing) {
  Image8 image{aliasing.width, aliasing.height, 3, {}};
  image.samples.reserve(aliasing.samples.size() * 3);
  for (float a : aliasing.samples) {
    const std::array<std::uint8_t, 3> rgb = aliasing_colour(a);
    image.samples.insert(image.samples.end(), rgb.begin(), rgb.end());
  }
  return image;
}

Image8 aliasing_legend() {
  Image8 legend{legend_width, legend_height, 3,
                std::vector<std::uint8_t>(static_cast<std::size_t>(legend_width) * legend_height * 3, background)};
  for (int x = 0; x <= octaves * tick_spacing; ++x) {
    const float factor = std::exp2(static_cast<float>(x) / tick_spacing - 3.0f);
    for (int y = bar_top; y < bar_bottom; ++y) set(legend, legend_margin + x, y, aliasing_colour(factor));
  }
  const char* labels[] = {"1/8", "1/4", "1/2", "1", "2", "4", "8"};
  for (int i = 0; i <= octaves; ++i) {
    const int x = legend_margin + i * tick_spacing;
    for (int y = bar_bottom; y < tick_bottom; ++y) set(legend, x, y, {ink, ink, ink});
    write(legend, labels[i], x, label_top);
  }
  return legend;
}

}  // namespace ecoview
