// A landscape's plants made cell by cell from (seed, cell, site) alone: the hash, the terrain,
// the cells' plants and their rules, and the expected surface of a cell.
#include "pointgen/landscape/hash32.hpp"
#include "pointgen/landscape/landscape_spec.hpp"
#include "pointgen/landscape/landscape_terrain.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace pointgen {
namespace {

LandscapeSpecies species(const std::string& name, float weight) {
  LandscapeSpecies s;
  s.name = name;
  s.weight = weight;
  return s;
}

// Two kilometres of hills and a valley, with trees, bushes and ground cover under every kind of
// rule.
LandscapeSpec forest() {
  LandscapeSpec spec;
  spec.seed = 67;
  spec.size = glm::vec2(2000.0f);
  spec.terrain = {.relief = 160.0f, .feature = 640.0f, .octaves = 6, .valley_depth = 60.0f, .valley_width = 400.0f,
                  .valley_meander = 300.0f, .valley_wavelength = 1500.0f};
  LandscapeLayer trees{"trees", 40.0f, 0.004f, {species("oak", 2.0f), species("pine", 1.0f)}};
  trees.species[0].altitude = {-1e9f, 10.0f};
  trees.species[0].grove = 0.5f;
  trees.species[0].grove_size = 200.0f;
  trees.species[1].altitude = {0.0f, 1e9f};
  trees.species[1].slope_max_deg = 20.0f;
  LandscapeLayer bushes{"bushes", 20.0f, 0.02f, {species("hazel", 1.0f)}};
  bushes.species[0].slope_max_deg = 15.0f;
  bushes.species[0].grove = 0.45f;
  LandscapeLayer ground{"ground", 8.0f, 0.5f, {species("grass", 5.0f), species("daisy", 1.0f)}};
  ground.species[1].altitude = {-20.0f, 20.0f};
  ground.species[1].tint_spread = 0.0f;
  spec.layers = {trees, bushes, ground};
  spec.check();
  return spec;
}

TEST(LandscapeHash32, IsXxHash32OfTheValuesAsLittleEndianWords) {
  // From libxxhash 0.8.1's XXH32 over the words 1, 0xFFFFFFFF, 7 (first 0 to 3 of them), seed 42.
  static_assert(hash32(0u) == 0x02CC5D05u, "XXH32 of nothing, seed 0");
  EXPECT_EQ(hash32(42u), 0xD5BE6EB8u);
  EXPECT_EQ(hash32(42u, 1), 0xB22F1493u);
  EXPECT_EQ(hash32(42u, 1, -1), 0x385575BDu) << "a signed value hashes as its two's complement bits";
  EXPECT_EQ(hash32(42u, 1u, 0xFFFFFFFFu, 7u), 0xBE575C68u);
  EXPECT_EQ(unit_float(0xFFFFFFFFu), 1.0f - 0x1p-24f);
  EXPECT_EQ(unit_float(0xFFu), 0.0f);
}

// Value noise may break where its lattice lines are (each octave's at multiples of feature /
// 2^octave, the valley's along x at multiples of its wavelength). Across each, the height steps
// no more than the slope on either side gives.
TEST(LandscapeTerrain, HeightsAgreeAcrossLatticeLines) {
  const LandscapeTerrainSpec spec{.relief = 160.0f, .feature = 640.0f, .octaves = 6, .valley_depth = 60.0f, .valley_width = 400.0f,
                                  .valley_meander = 300.0f, .valley_wavelength = 1500.0f};
  const LandscapeTerrain terrain(spec, 67);
  std::vector<float> borders;
  const float finest = spec.feature / static_cast<float>(1 << (spec.octaves - 1));
  for (int k = -40; k <= 40; k += 3) borders.push_back(finest * static_cast<float>(k));
  for (int k = -1; k <= 1; ++k) borders.push_back(spec.valley_wavelength * static_cast<float>(k));
  constexpr float step = 0.01f;
  auto step_across = [&](float b, float along, bool across_x, float from, float to) {
    return std::abs(across_x ? terrain.height(b + to, along) - terrain.height(b + from, along)
                             : terrain.height(along, b + to) - terrain.height(along, b + from));
  };
  for (float b : borders) {
    for (float along = -900.0f; along <= 900.0f; along += 37.0f) {
      for (bool across_x : {true, false}) {
        const float jump = step_across(b, along, across_x, -step, step);
        const float sides = std::max(step_across(b, along, across_x, step, 3.0f * step), step_across(b, along, across_x, -3.0f * step, -step));
        EXPECT_LE(jump, 2.0f * sides + 1e-3f) << "across " << (across_x ? "x = " : "z = ") << b << " at " << along;
      }
    }
  }
}

TEST(LandscapeSpec, CheckNamesTheFirstFieldOutOfRange) {
  LandscapeSpec spec = forest();
  spec.layers[1].species[0].scale = {2.0f, 1.0f};
  try {
    spec.check();
    FAIL() << "a reversed scale range passed";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("layers[1].species[0].scale:", 0), 0u) << e.what();
  }
  spec = forest();
  spec.size.x = 2.0f * LandscapeSpec::max_size;
  EXPECT_THROW(spec.check(), std::invalid_argument);
}

}  // namespace
}  // namespace pointgen
