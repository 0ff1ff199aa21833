// The PSM's near plane comes from the nearest depth a frame shows, reduced on the GPU block by
// block: against the least positive value of the same depths, found here on the CPU.
#include "app/gl/context.hpp"
#include "app/render/nearest_depth.hpp"
#include "pointgen/random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace ecoview {
namespace {

// Depths of a frame whose sides are no multiple of the block: metres, -1 where nothing was drawn.
class NearestDepthTest : public testing::Test {
 protected:
  static constexpr int width = 333, height = 185;

  float gpu_nearest(const std::vector<float>& depths) {
    gl::Texture texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.name(), 1, GL_R32F, width, height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(texture.name(), 0, 0, 0, width, height, GL_RED, GL_FLOAT, depths.data());
    return NearestDepth(width, height).read(texture.name());
  }

  std::unique_ptr<GlContext> context_ = create_headless_context("egl");
};

TEST_F(NearestDepthTest, IsTheLeastDrawnDepthWhereverItLies) {
  pointgen::Random random(11);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<float> depths(static_cast<std::size_t>(width) * height);
    for (float& d : depths) d = random.uniform() < 0.3f ? -1.0f : random.uniform(2.0f, 500.0f);
    // One nearer pixel, in the last partial block in some trials.
    const std::size_t at = trial % 2 ? depths.size() - 1 : random.below(static_cast<std::uint32_t>(depths.size()));
    depths[at] = random.uniform(0.05f, 1.9f);
    float expected = INFINITY;
    for (float d : depths) {
      if (d > 0.0f) expected = std::min(expected, d);
    }
    EXPECT_EQ(gpu_nearest(depths), expected) << "trial " << trial;
  }
}

TEST_F(NearestDepthTest, IsZeroWhereNothingWasDrawn) {
  EXPECT_EQ(gpu_nearest(std::vector<float>(static_cast<std::size_t>(width) * height, -1.0f)), 0.0f);
}

}  // namespace
}  // namespace ecoview
