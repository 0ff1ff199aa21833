// A landscape's plants made cell by cell from (seed, cell, site) alone: the hash, the terrain,
// the cells' plants and their rules, and the expected surface of a cell.
#include "pointgen/landscape/hash32.hpp"

#include <gtest/gtest.h>

namespace pointgen {
namespace {

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

}  // namespace
}  // namespace pointgen
