#include "app/capture/aliasing_colours.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ecoview {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

TEST(AliasingColours, GoFromBlueAtAnEighthThroughGreenAtOneToRedAtEight) {
  EXPECT_EQ(aliasing_colour(0.125f), (Rgb{0, 0, 255}));
  EXPECT_EQ(aliasing_colour(1.0f), (Rgb{0, 255, 0}));
  EXPECT_EQ(aliasing_colour(8.0f), (Rgb{255, 0, 0}));
  EXPECT_EQ(aliasing_colour(1000.0f), (Rgb{255, 0, 0}));   // the light grazing the surface
  EXPECT_EQ(aliasing_colour(0.001f), (Rgb{0, 0, 255}));
  EXPECT_EQ(aliasing_colour(0.0f), (Rgb{0, 0, 0}));        // no surface or no map
  EXPECT_EQ(aliasing_colour(NAN), (Rgb{0, 0, 0}));
}

TEST(AliasingLegend, ItsBarHasTheHeatMapsColourAboveEachLabelledTick) {
  const Image8 legend = aliasing_legend();
  // Ticks every 48 pixels from x = 20 for 1/8, 1/4, ..., 8; the bar's rows are 4 to 23.
  for (int i = 0; i <= 6; ++i) {
    const Rgb expected = aliasing_colour(std::exp2(static_cast<float>(i - 3)));
    const int x = 20 + 48 * i;
    EXPECT_EQ((Rgb{legend.at(x, 12, 0), legend.at(x, 12, 1), legend.at(x, 12, 2)}), expected) << "tick " << i;
    EXPECT_EQ(legend.at(x, 26, 0), 255) << "tick mark " << i;
  }
}

}  // namespace
}  // namespace ecoview
