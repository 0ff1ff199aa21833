// The CPU aliasing factor against a texel size worked out by hand, the percentile it is reported
// by, and the prediction `auto` chooses by against the PSM paper's best case.
#include "random_setups.hpp"
#include "shadow/aliasing.hpp"
#include "shadow/psm_map.hpp"
#include "shadow/uniform_map.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace shadow {
namespace {

TEST(Percentile, OfASmallList) {
  EXPECT_EQ(percentile({5, 1, 3, 2, 4}, 0.5f), 3.0f);  // the median
  EXPECT_EQ(percentile({5, 1, 3, 2, 4}, 0.0f), 1.0f);
  EXPECT_EQ(percentile({5, 1, 3, 2, 4}, 1.0f), 5.0f);
  EXPECT_EQ(percentile({}, 0.5f), 0.0f);
}

// A 20 m orthographic map of 1024 texels along a sun tilted by theta from the ground's normal
// (in the xy plane): a texel is 20/1024 m across the beam, so on the ground it spans
// 20/1024 / cos(theta) along x and 20/1024 along z. A camera 10 m up looking straight down with a
// 90° field of view over 512 pixels sees 25.6 pixels a metre everywhere on the ground (a plane
// parallel to the image), so the largest stretch is 0.5 / cos(theta) pixels, at every point.
TEST(AliasingFactor, IsTheTexelStretchedByOneOverCosineOfTheLightsTilt) {
  Camera camera = camera_looking({0, 10, 0}, {0, 0, 0}, 0.1f, 200.0f);
  camera.up = {0, 0, -1};
  camera.fov_y_deg = 90.0f;
  const FrameView frame{camera.projection(1.0f) * camera.view(), {512, 512}};
  std::vector<SurfacePoint> ground, underside;
  for (float x = -4.0f; x <= 4.0f; x += 2.0f) {
    for (float z = -4.0f; z <= 4.0f; z += 2.0f) {
      ground.push_back({{x, 0, z}, {0, 1, 0}});
      underside.push_back({{x, 0, z}, {0, -1, 0}});
    }
  }
  for (float theta_deg : {0.0f, 30.0f, 60.0f, 75.0f}) {
    const float theta = glm::radians(theta_deg);
    const glm::vec3 direction(std::sin(theta), -std::cos(theta), 0.0f);
    const Light sun{LightType::directional, {}, direction, 30};
    ShadowSetup setup;
    setup.views.push_back({glm::lookAt(-50.0f * direction, glm::vec3(0), glm::vec3(0, 0, -1)),
                           glm::ortho(-10.0f, 10.0f, -10.0f, 10.0f, 1.0f, 100.0f)});
    const float expected = 0.5f / std::cos(theta);
    EXPECT_NEAR(aliasing_factor(setup, sun, 1024, frame, {1, 0, -2}, {0, 1, 0}), expected, 0.01f * expected) << theta_deg;
    EXPECT_NEAR(aliasing_factor(setup, sun, 2048, frame, {1, 0, -2}, {0, 1, 0}), expected / 2, 0.01f * expected) << theta_deg;
    EXPECT_NEAR(predicted_aliasing(setup, sun, 1024, frame, ground, median_fraction), expected, 0.01f * expected) << theta_deg;
    EXPECT_EQ(predicted_aliasing(setup, sun, 1024, frame, underside, median_fraction), 0.0f);  // the sun faces none
  }
}

// Seed 000, Sect. 3.3: with the light across the view over a deep scene the PSM's texels near the
// eye are far smaller; the prediction must see it.
TEST(PredictedAliasing, FavoursThePsmForALightAcrossADeepView) {
  const Camera camera = deep_view_camera();
  const float aspect = 16.0f / 9.0f;
  const Light sun{LightType::directional, {}, glm::normalize(glm::vec3(1, -1, 0)), 30};
  const FrameView frame{camera.projection(aspect) * camera.view(), {960, 540}};
  std::vector<SurfacePoint> ground;  // the ground the camera sees, 2 to 90 m ahead
  for (float z = 43.0f; z > -45.0f; z -= 2.0f) {
    for (float x = -10.0f; x <= 10.0f; x += 2.0f) ground.push_back({{x, 0, z}, {0, 1, 0}});
  }
  const float psm = predicted_aliasing(perspective_shadow_map({camera, aspect, sun, scene_box(), 1024}), sun, 1024, frame, ground, p95_fraction);
  const float uniform = predicted_aliasing(focused_uniform_map({camera, aspect, sun, scene_box(), 1024}), sun, 1024, frame, ground, p95_fraction);
  EXPECT_GT(psm, 0.0f);
  EXPECT_LT(psm, uniform / 2.0f);
}

}  // namespace
}  // namespace shadow
