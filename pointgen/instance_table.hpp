#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pointgen {

// A tint (linear RGB, each channel from 0 to 2) in 32 bits: per channel the square root of half
// its value in 10 bits, so that its steps are finest near black, as sRGB's are: from 0 to 1 a
// channel stays within a quarter of a step of 8-bit sRGB, above 1 within 0.2 % of its value.
constexpr float tint_bits = 1023.0f;
inline std::uint32_t pack_tint(const glm::vec3& tint) {
  std::uint32_t packed = 0;
  for (int c = 0; c < 3; ++c) {
    const float encoded = std::sqrt(std::clamp(tint[c], 0.0f, 2.0f) / 2.0f);
    packed |= static_cast<std::uint32_t>(std::lround(encoded * tint_bits)) << (10 * c);
  }
  return packed;
}
inline glm::vec3 unpack_tint(std::uint32_t packed) {
  glm::vec3 tint;
  for (int c = 0; c < 3; ++c) {
    const float encoded = static_cast<float>((packed >> (10 * c)) & 0x3FFu) / tint_bits;
    tint[c] = 2.0f * encoded * encoded;
  }
  return tint;
}

// Instances of one mesh: each a transform, a tint (multiplied with the mesh's colours) and a seed
// (for anything random about it later, such as its sample points). Transforms are affine, so a
// table keeps their top three rows (glm::mat4x3: 48 bytes, where a mat4 takes 64), tints packed
// and seeds of 32 bits: 56 bytes an instance, which is what ten million plants cost in memory
// beyond their species' meshes.
struct InstanceTable {
  std::size_t mesh = 0;
  std::vector<glm::mat4x3> transforms;
  std::vector<std::uint32_t> tints;  // pack_tint's
  std::vector<std::uint32_t> seeds;
  // Each instance stands for several (a landscape's far picks): its count, below one, rounds up
  // to one point wherever any is asked, where others' round at a threshold from their seeds.
  bool rounds_up = false;
  static constexpr float round_up_threshold = 0.99999994f;  // the largest float below 1

  std::size_t size() const { return transforms.size(); }
  glm::mat4 transform(std::size_t i) const { return glm::mat4(transforms[i]); }
  glm::vec3 tint(std::size_t i) const { return unpack_tint(tints[i]); }
  // `transform` must be affine (its last row 0 0 0 1); a seed keeps its low 32 bits.
  void add(const glm::mat4& transform, const glm::vec3& tint, std::uint64_t seed) {
    transforms.emplace_back(transform);
    tints.push_back(pack_tint(tint));
    seeds.push_back(static_cast<std::uint32_t>(seed));
  }
  // Adds instance `i` of `from` as it is kept there (no unpacking and packing again).
  void add_from(const InstanceTable& from, std::size_t i) {
    transforms.push_back(from.transforms[i]);
    tints.push_back(from.tints[i]);
    seeds.push_back(from.seeds[i]);
  }
  // Gives back the room that growing by add() left unfilled (up to half of a table).
  void shrink_to_fit() {
    transforms.shrink_to_fit();
    tints.shrink_to_fit();
    seeds.shrink_to_fit();
  }
};

// The scale of an instance's transform (the cube root of its volume change).
inline float uniform_scale(const glm::mat4& transform) { return std::cbrt(std::abs(glm::determinant(glm::mat3(transform)))); }

}  // namespace pointgen
