#include "app/bench/density_figures.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ecoview {
namespace {

RenderedFrame frame(const std::vector<float>& depth) {
  const int n = static_cast<int>(depth.size());
  return {Image8{n, 1, 3, std::vector<std::uint8_t>(3 * depth.size(), 100)}, Image<float>{n, 1, 1, depth}};
}

// Eight pixels: one behind an occluder, one empty in the reference, six covered at depths 1 to 6
// in shuffled order; the points cover all but the one at depth 5.
DensityRenders eight_pixels() {
  DensityRenders r;
  r.polygons = frame({5, 1, 3, 9, -1, 2, 6, 4});
  r.occluders = frame({-1, -1, -1, 8, -1, -1, -1, -1});
  r.points = frame({-1, 1, 3, 8, -1, 2, 6, 4});
  r.points_in_scene = r.points;
  r.polygons_in_scene = r.polygons;
  r.reference = r.polygons.color;
  return r;
}

TEST(DensityFigures, HolesAreCoveredPixelsThePointsMiss) {
  const DensityFigures f = density_figures(eight_pixels(), Image<std::uint32_t>{8, 1, 1, std::vector<std::uint32_t>(8, 1)});
  EXPECT_EQ(f.covered, 6u);
  EXPECT_DOUBLE_EQ(f.holes, 1.0 / 6.0);
}

TEST(DensityFigures, ThirdsSplitTheCoveredPixelsByDepth) {
  // Counts chosen so that each pair of depths (1, 2), (3, 4), (5, 6) has its own mean.
  const Image<std::uint32_t> counts{8, 1, 1, {10, 1, 5, 99, 99, 3, 14, 7}};
  const DensityFigures f = density_figures(eight_pixels(), counts);
  EXPECT_DOUBLE_EQ(f.pts_per_px_near, 2.0);    // depths 1 and 2: counts 1 and 3
  EXPECT_DOUBLE_EQ(f.pts_per_px_middle, 6.0);  // depths 3 and 4: 5 and 7
  EXPECT_DOUBLE_EQ(f.pts_per_px_far, 12.0);    // depths 5 and 6: 10 and 14
  EXPECT_DOUBLE_EQ(f.pts_per_px, 40.0 / 6.0);
  EXPECT_FLOAT_EQ(f.third_depths[0], 1.0f);
  EXPECT_FLOAT_EQ(f.third_depths[1], 3.0f);
  EXPECT_FLOAT_EQ(f.third_depths[2], 5.0f);
  EXPECT_FLOAT_EQ(f.third_depths[3], 6.0f);
}

TEST(DensityFigures, QualityIsMeasuredWhereEitherRenderShowsAPointObject) {
  // The points alone show pixel 4 (empty in the polygon render), in another colour than the
  // reference's there: the points lose PSNR, the polygons (equal to the reference) score 99 dB.
  DensityRenders r = eight_pixels();
  r.points.depth.samples[4] = r.points_in_scene.depth.samples[4] = 7.0f;
  for (int c = 0; c < 3; ++c) r.points_in_scene.color.samples[3 * 4 + c] = 200;
  const FidelityFigures f = fidelity_figures(r);
  EXPECT_DOUBLE_EQ(f.psnr_polygons, 99.0);
  EXPECT_NEAR(f.ssim_polygons, 1.0, 1e-12);
  // 7 measured pixels (6 covered by the polygons, 1 by the points alone), one off by 100.
  EXPECT_NEAR(f.psnr, 10.0 * std::log10(255.0 * 255.0 * 7.0 / (100.0 * 100.0)), 1e-9);
  EXPECT_LT(f.ssim, 1.0);
}

TEST(DensityFigures, QualityLeavesOutPixelsWhereTheGroundHidesThePlants) {
  // Ground before the plant at pixel 1 in the whole scene (depth 0.5 against the plant's 1): the
  // points' wrong colour there is not counted, as the frame does not show the plant.
  DensityRenders r = eight_pixels();
  r.points_in_scene.depth.samples[1] = r.polygons_in_scene.depth.samples[1] = 0.5f;
  for (int c = 0; c < 3; ++c) r.points_in_scene.color.samples[3 * 1 + c] = 0;
  EXPECT_DOUBLE_EQ(fidelity_figures(r).psnr, 99.0);
}

}  // namespace
}  // namespace ecoview
