#include "pointgen/surface_texture.hpp"

#include "pointgen/srgb.hpp"

#include <array>
#include <cmath>

namespace pointgen {
namespace {

const std::array<float, 256>& srgb_to_linear_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      t[static_cast<std::size_t>(i)] = srgb_to_linear(static_cast<float>(i) / 255.0f);
    }
    return t;
  }();
  return table;
}

// The texel index for integer coordinate i along an axis of n texels.
int wrapped(int i, int n, SurfaceTexture::Wrap wrap) {
  switch (wrap) {
    case SurfaceTexture::Wrap::clamp: return i < 0 ? 0 : i >= n ? n - 1 : i;
    case SurfaceTexture::Wrap::mirror: {
      const int period = 2 * n;
      int m = i % period;
      if (m < 0) m += period;
      return m < n ? m : period - 1 - m;
    }
    case SurfaceTexture::Wrap::repeat: break;
  }
  const int m = i % n;
  return m < 0 ? m + n : m;
}

}  // namespace

glm::vec4 SurfaceTexture::sample(glm::vec2 uv) const {
  if (width <= 0 || height <= 0) return glm::vec4(1.0f);
  // Texel centres at (i + 0.5) / width. A repeating or mirrored axis is folded into [0, 2) first
  // (both repeat over 2 texture widths), so far-off coordinates keep the float's precision.
  const auto fold = [](float x, Wrap wrap) { return wrap == Wrap::clamp ? x : x - 2.0f * std::floor(0.5f * x); };
  const glm::vec2 p = glm::vec2(fold(uv.x, wrap_s), fold(uv.y, wrap_t)) * glm::vec2(width, height) - 0.5f;
  const glm::vec2 base = glm::floor(glm::clamp(magnify == Filter::nearest ? p + 0.5f : p, glm::vec2(-1e6f), glm::vec2(1e6f)));
  // The second texel's weight on each axis (none when nearest); beyond a clamped edge, the edge texel.
  const glm::vec2 f = magnify == Filter::nearest ? glm::vec2(0.0f) : glm::clamp(p - base, 0.0f, 1.0f);
  const auto& linear = srgb_to_linear_table();
  glm::vec4 sum(0.0f);
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      const int x = wrapped(static_cast<int>(base.x) + dx, width, wrap_s);
      const int y = wrapped(static_cast<int>(base.y) + dy, height, wrap_t);
      const std::uint8_t* t = &rgba[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x))];
      const float weight = (dx ? f.x : 1.0f - f.x) * (dy ? f.y : 1.0f - f.y);
      sum += weight * glm::vec4(linear[t[0]], linear[t[1]], linear[t[2]], static_cast<float>(t[3]) / 255.0f);
    }
  }
  return sum;
}

glm::vec4 SurfaceMaterial::texel(glm::vec2 uv) const { return texture ? texture->sample(uv) : glm::vec4(1.0f); }

float SurfaceMaterial::keep_scale(float vertex_alpha) const { return masked() ? alpha * vertex_alpha / alpha_cutoff : -1.0f; }

}  // namespace pointgen
