// The bench's frame-to-frame figures on a row of pixels whose changes the test sets itself.
#include "app/bench/shadow_figures.hpp"

#include <gtest/gtest.h>

namespace ecoview {
namespace {

// Visibility of a row of pixels: '#' shadowed, '.' lit.
Image8 row(const std::string& states) {
  Image8 image{static_cast<int>(states.size()), 1, 1, {}};
  for (const char c : states) image.samples.push_back(c == '#' ? 0 : 255);
  return image;
}

// Six surface pixels and one of sky (depth 0). The reference changes at pixels 0 and 1; the frame
// changes at 1 (as the reference does) and at 2 and 3 (where it does not), and at the sky pixel.
TEST(ShadowFigures, TemporalErrCountsThePixelsThatChangeOtherwiseThanTheReference) {
  const Image<float> depth{7, 1, 1, {1, 2, 3, 4, 5, 6, 0}};
  const Image8 reference_before = row("#......"), reference_after = row(".#.....");
  const Image8 before = row("...#..."), after = row(".##...#");
  EXPECT_DOUBLE_EQ(changed_shadow(reference_before, reference_after, depth), 2.0 / 6.0);
  EXPECT_DOUBLE_EQ(changed_shadow(before, after, depth), 3.0 / 6.0);
  // 0: the reference changed, the frame did not; 2 and 3: the frame changed alone.
  EXPECT_DOUBLE_EQ(temporal_err(before, after, reference_before, reference_after, depth), 3.0 / 6.0);
}

}  // namespace
}  // namespace ecoview
