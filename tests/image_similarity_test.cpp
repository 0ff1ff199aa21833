#include "app/bench/image_similarity.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ecoview {
namespace {

Image8 grey(int width, int height, std::uint8_t value) {
  return {width, height, 3, std::vector<std::uint8_t>(static_cast<std::size_t>(width * height * 3), value)};
}

// Alternate pixels dark and light, or light and dark where `inverted`.
Image8 checkers(int width, int height, bool inverted) {
  Image8 image = grey(width, height, 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::uint8_t v = ((x + y) % 2 == 0) != inverted ? 40 : 210;
      for (int c = 0; c < 3; ++c) image.samples[static_cast<std::size_t>((y * width + x) * 3 + c)] = v;
    }
  }
  return image;
}

TEST(Ssim, IsOneForAnImageAgainstItself) {
  const Image8 image = checkers(23, 17, false);
  EXPECT_NEAR(ssim_over(std::vector<bool>(23 * 17, true), image, image), 1.0, 1e-12);
}

TEST(Ssim, OfTwoFlatImagesIsTheLuminanceTermOfTheirMeans) {
  // No variance anywhere: the contrast-structure term is C2 / C2, what is left is Wang et al.'s
  // luminance comparison of the two greys (luminance weights sum to 1, so a grey is its own).
  const double c1 = (0.01 * 255) * (0.01 * 255);
  const double expected = (2.0 * 100 * 150 + c1) / (100.0 * 100 + 150.0 * 150 + c1);
  EXPECT_NEAR(ssim_over(std::vector<bool>(20 * 12, true), grey(20, 12, 100), grey(20, 12, 150)), expected, 1e-9);
}

TEST(Ssim, OfAPatternAgainstItsInverseIsNearMinusOne) {
  // Equal means where the window holds as many dark as light pixels; the covariance is minus the
  // variance. Only the pixels away from the edges, where the window is whole.
  std::vector<bool> inner(31 * 31, false);
  for (int y = 5; y < 26; ++y) {
    for (int x = 5; x < 26; ++x) inner[static_cast<std::size_t>(y * 31 + x)] = true;
  }
  EXPECT_LT(ssim_over(inner, checkers(31, 31, false), checkers(31, 31, true)), -0.9);
}

TEST(Ssim, CountsOnlyTheMarkedPixels) {
  // The right half differs; marking only the left half's far side leaves the score at 1.
  Image8 changed = grey(40, 10, 90);
  const Image8 reference = grey(40, 10, 90);
  for (int y = 0; y < 10; ++y) {
    for (int x = 20; x < 40; ++x) changed.samples[static_cast<std::size_t>((y * 40 + x) * 3)] = 250;
  }
  std::vector<bool> left(40 * 10, false);
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 8; ++x) left[static_cast<std::size_t>(y * 40 + x)] = true;  // 12 pixels from the change: outside the window
  }
  EXPECT_NEAR(ssim_over(left, reference, changed), 1.0, 1e-12);
  EXPECT_LT(ssim_over(std::vector<bool>(400, true), reference, changed), 0.9);
}

TEST(Psnr, IsTheMeanSquaredErrorOfTheMarkedSamplesInDecibels) {
  // Every sample off by 16 in the marked pixels: 10 log10(255² / 256).
  const Image8 a = grey(6, 4, 100), b = grey(6, 4, 116);
  std::vector<bool> pixels(24, false);
  pixels[3] = pixels[17] = true;
  EXPECT_NEAR(psnr_over(pixels, a, b), 10.0 * std::log10(255.0 * 255.0 / 256.0), 1e-9);
}

TEST(BoxFilter, AveragesEachBlockInLinearLight) {
  // A 4 × 4 block half black, half white is half the light: sRGB 0.5 linear, about 188 of 255.
  Image8 image = grey(8, 4, 0);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 2; ++x) {
      for (int c = 0; c < 3; ++c) image.samples[static_cast<std::size_t>((y * 8 + x) * 3 + c)] = 255;
    }
  }
  for (int x = 4; x < 8; ++x) {
    for (int c = 0; c < 3; ++c) image.samples[static_cast<std::size_t>((2 * 8 + x) * 3 + c)] = 255;  // one row of four: a quarter
  }
  const Image8 small = box_filtered(image, 4);
  ASSERT_EQ(small.width, 2);
  ASSERT_EQ(small.height, 1);
  const auto srgb = [](double linear) { return 255.0 * (1.055 * std::pow(linear, 1.0 / 2.4) - 0.055); };
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(small.at(0, 0, c), srgb(0.5), 0.5 + 1e-9);
    EXPECT_NEAR(small.at(1, 0, c), srgb(0.25), 0.5 + 1e-9);
  }
}

}  // namespace
}  // namespace ecoview
