#pragma once
#include <cstdint>

// Value noise on hash32's lattice: a random value at every integer point, blended with Perlin's
// (2002) quintic so that heights and their slopes are continuous across lattice lines. Each
// lattice value comes from (seed, octave, i, j) alone, so any point is computed without a table.
namespace pointgen {

// Along a line, in [0, 1]: lattice values at the integers.
float value_noise(std::uint32_t seed, float x);
// Over the plane, in [0, 1]: octave `octave`'s own lattice (seed, octave, i, j).
float value_noise(std::uint32_t seed, int octave, float x, float z);
// `octaves` octaves of value_noise, each of twice the frequency and half the amplitude of the one
// before, in [0, 1].
float fractal_noise(std::uint32_t seed, int octaves, float x, float z);

}  // namespace pointgen
