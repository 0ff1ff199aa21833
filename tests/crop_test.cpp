// The report's crops: a rectangle of the frame, each pixel a block of factor × factor.
#include "app/bench/crop.hpp"

#include <gtest/gtest.h>

namespace ecoview::test {
namespace {

TEST(Crop, EachPixelOfTheRectangleBecomesASquareBlockOfIt) {
  Image8 frame{5, 4, 3, {}};
  for (int i = 0; i < 5 * 4 * 3; ++i) frame.samples.push_back(static_cast<std::uint8_t>(i));  // every sample different
  const Image8 crop = magnified_crop(frame, {1, 2, 3, 2}, 3);
  ASSERT_EQ(crop.width, 9);
  ASSERT_EQ(crop.height, 6);
  ASSERT_EQ(crop.channels, 3);
  ASSERT_EQ(crop.samples.size(), 9u * 6u * 3u);
  for (int block_y = 0; block_y < 2; ++block_y) {
    for (int block_x = 0; block_x < 3; ++block_x) {
      for (int dy = 0; dy < 3; ++dy) {
        for (int dx = 0; dx < 3; ++dx) {
          for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(crop.at(3 * block_x + dx, 3 * block_y + dy, c), frame.at(1 + block_x, 2 + block_y, c));
          }
        }
      }
    }
  }
}

// A lit image with one checkered patch: the rectangle chosen holds its middle.
TEST(Crop, IsTakenWhereTheShadowsHaveTheMostEdges) {
  Image8 visibility{80, 40, 1, std::vector<std::uint8_t>(80 * 40, 255)};
  for (int y = 26; y < 34; ++y) {
    for (int x = 50; x < 58; ++x) visibility.samples[static_cast<std::size_t>(y * 80 + x)] = (x + y) % 2 ? 0 : 255;
  }
  const PixelRect rect = busiest_shadow_edges(visibility, 20, 10);
  EXPECT_EQ(rect.width, 20);
  EXPECT_EQ(rect.height, 10);
  EXPECT_TRUE(rect.x <= 54 && 54 < rect.x + rect.width) << rect.x;
  EXPECT_TRUE(rect.y <= 30 && 30 < rect.y + rect.height) << rect.y;
}

}  // namespace
}  // namespace ecoview::test
