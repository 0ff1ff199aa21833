#include "pointgen/placement/terrain.hpp"

#include "pointgen/placement/height_grid_mesh.hpp"
#include "pointgen/random.hpp"

#include <algorithm>
#include <cmath>

namespace pointgen {
namespace {

// Smooth value noise in [0, 1]: random values on the integer lattice, blended with a quintic.
float value_noise(std::uint64_t seed, float x, float y) {
  const float fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
  auto lattice = [&](std::int64_t i, std::int64_t j) {
    return static_cast<float>(derive_seed(derive_seed(seed, static_cast<std::uint64_t>(i)), static_cast<std::uint64_t>(j)) >> 40) /
           16777216.0f;
  };
  auto fade = [](float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); };
  const float u = fade(x - fx), v = fade(y - fy);
  const float a = lattice(ix, iy), b = lattice(ix + 1, iy), c = lattice(ix, iy + 1), d = lattice(ix + 1, iy + 1);
  return (a + (b - a) * u) + ((c + (d - c) * u) - (a + (b - a) * u)) * v;
}

// Fractal sum of four octaves, in [0, 1].
float fractal_noise(std::uint64_t seed, float x, float y) {
  float sum = 0.0f, amplitude = 0.5f, total = 0.0f;
  for (int octave = 0; octave < 4; ++octave) {
    sum += amplitude * value_noise(derive_seed(seed, static_cast<std::uint64_t>(octave)), x, y);
    total += amplitude;
    amplitude *= 0.5f;
    x *= 2.0f;
    y *= 2.0f;
  }
  return sum / total;
}

}  // namespace

Terrain::Terrain(const TerrainSpec& spec) : spec_(spec) {
  const float longer = std::max(spec.size.x, spec.size.y);
  const float step = longer / static_cast<float>(std::max(1, spec.resolution));
  cells_ = glm::max(glm::ivec2(1), glm::ivec2(glm::ceil(spec.size / step)));
  origin_ = spec.center - 0.5f * spec.size;
  cell_ = spec.size / glm::vec2(cells_);
  heights_.reserve(static_cast<std::size_t>((cells_.x + 1) * (cells_.y + 1)));
  for (int j = 0; j <= cells_.y; ++j) {
    for (int i = 0; i <= cells_.x; ++i) {
      const glm::vec2 p = origin_ + glm::vec2(i, j) * cell_;
      heights_.push_back(spec.relief * (fractal_noise(spec.seed, p.x / spec.feature, p.y / spec.feature) - 0.5f));
    }
  }
}

float Terrain::height(float x, float z) const {
  const glm::vec2 g = glm::clamp((glm::vec2(x, z) - origin_) / cell_, glm::vec2(0.0f), glm::vec2(cells_));
  const glm::ivec2 c = glm::min(glm::ivec2(g), cells_ - 1);
  const glm::vec2 f = g - glm::vec2(c);
  const float h00 = grid(c.x, c.y), h10 = grid(c.x + 1, c.y), h01 = grid(c.x, c.y + 1), h11 = grid(c.x + 1, c.y + 1);
  // Each cell is split along its diagonal from (0, 0) to (1, 1), as mesh() does.
  if (f.x >= f.y) return h00 + (h10 - h00) * f.x + (h11 - h10) * f.y;
  return h00 + (h11 - h01) * f.x + (h01 - h00) * f.y;
}

TriangleMesh Terrain::mesh() const {
  return height_grid_mesh(
      cells_,
      [this](int i, int j) {
        const glm::vec2 p = origin_ + glm::vec2(i, j) * cell_;
        return glm::vec3(p.x, grid(i, j), p.y);
      },
      spec_.relief, {spec_.low_color, spec_.high_color});
}

}  // namespace pointgen
