#pragma once
#include <cstdint>

// The landscape's random numbers: one integer hash of (seed, a few integers) in 32-bit unsigned
// arithmetic alone (no 64-bit products, no floats), so that a shader can compute the same bits
// and any plant can be made from its own key without the ones before it.
namespace pointgen {

namespace hash32_primes {
constexpr std::uint32_t p1 = 2654435761u, p2 = 2246822519u, p3 = 3266489917u, p4 = 668265263u, p5 = 374761393u;
}

constexpr std::uint32_t rotate_left(std::uint32_t x, int r) { return (x << r) | (x >> (32 - r)); }

// xxHash32's round for a message shorter than 16 bytes (Collet 2012), one 4-byte word a value,
// and its avalanche: Jarzynski and Olano (2020) find it the best of the fast GPU hashes with more
// than one input. Signed values hash as their two's complement bits, as a shader's uint() does.
template <class... Values>
constexpr std::uint32_t hash32(std::uint32_t seed, Values... values) {
  using namespace hash32_primes;
  std::uint32_t h = seed + p5 + 4u * static_cast<std::uint32_t>(sizeof...(Values));
  ((h = rotate_left(h + static_cast<std::uint32_t>(values) * p3, 17) * p4), ...);
  h ^= h >> 15;
  h *= p2;
  h ^= h >> 13;
  h *= p3;
  return h ^ (h >> 16);
}

// Uniform in [0, 1), from the top 24 bits so every value is exact in a float.
constexpr float unit_float(std::uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

}  // namespace pointgen
