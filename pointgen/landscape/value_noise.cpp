#include "pointgen/landscape/value_noise.hpp"

#include "pointgen/landscape/hash32.hpp"

#include <cmath>

namespace pointgen {
namespace {

float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

std::int32_t lattice_index(float x) { return static_cast<std::int32_t>(std::floor(x)); }

}  // namespace

float value_noise(std::uint32_t seed, float x) {
  const std::int32_t i = lattice_index(x);
  const float u = fade(x - static_cast<float>(i));
  const float a = unit_float(hash32(seed, i)), b = unit_float(hash32(seed, i + 1));
  return a + (b - a) * u;
}

float value_noise(std::uint32_t seed, int octave, float x, float z) {
  const std::int32_t i = lattice_index(x), j = lattice_index(z);
  const float u = fade(x - static_cast<float>(i)), v = fade(z - static_cast<float>(j));
  const float a = unit_float(hash32(seed, octave, i, j)), b = unit_float(hash32(seed, octave, i + 1, j));
  const float c = unit_float(hash32(seed, octave, i, j + 1)), d = unit_float(hash32(seed, octave, i + 1, j + 1));
  const float near = a + (b - a) * u, far = c + (d - c) * u;
  return near + (far - near) * v;
}

float fractal_noise(std::uint32_t seed, int octaves, float x, float z) {
  float sum = 0.0f, amplitude = 0.5f, total = 0.0f;
  for (int octave = 0; octave < octaves; ++octave) {
    sum += amplitude * value_noise(seed, octave, x, z);
    total += amplitude;
    amplitude *= 0.5f;
    x *= 2.0f;
    z *= 2.0f;
  }
  return sum / total;
}

}  // namespace pointgen
