#pragma once
#include <glm/glm.hpp>

#include <cstdint>

// The project's one random-number scheme: a seed per scene, a seed per instance derived by
// hashing (scene seed, instance id), and a small generator whose integers and uniforms are the
// same on every platform and compiler (unlike std:: distributions). Geometry built from them also
// goes through std::sin, std::exp and the like, whose last bits may differ between C libraries:
// the same frame gives the same bytes on the same platform.
namespace pointgen {

// SplitMix64's finalizer: a strong 64-bit mix.
constexpr std::uint64_t mix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// The seed of item `id` under `seed` (an instance under the scene, a species under a catalogue).
constexpr std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t id) { return mix64(mix64(seed) ^ id); }

class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    state_ += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1), from the top 24 bits so every value is exact in a float.
  float uniform() { return static_cast<float>(next() >> 40) * (1.0f / 16777216.0f); }
  float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
  // Uniform in [0, 1) with 53 random bits, for picks among millions of items.
  double uniform_double() { return static_cast<double>(next() >> 11) * 0x1p-53; }
  // Uniform integer in [0, n).
  std::uint32_t below(std::uint32_t n) { return static_cast<std::uint32_t>((next() >> 32) * n >> 32); }
  // A direction in the unit disc, and around a mean with a relative spread.
  glm::vec2 in_disc() {
    for (;;) {
      const glm::vec2 p(uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f));
      if (glm::dot(p, p) <= 1.0f) return p;
    }
  }

 private:
  std::uint64_t state_;
};

}  // namespace pointgen
