// The CPU aliasing factor against a texel size worked out by hand, and the prediction `auto`
// chooses by against the PSM paper's best case.
#include "random_setups.hpp"
#include "shadow/aliasing.hpp"
#include "shadow/psm_map.hpp"
#include "shadow/uniform_map.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace shadow {
namespace {

// A sun straight down over a 20 m square map of 1024 texels: texels of 20/1024 m. A camera 10 m
// over the ground looking straight down with a 90° field of view sees 20 m across 512 pixels, 25.6
// pixels a metre: a texel is 0.5 pixels.
TEST(AliasingFactor, MatchesATexelSizeWorkedOutByHand) {
  const Light sun{LightType::directional, {}, {0, -1, 0}, 30};
  ShadowSetup setup;
  setup.views.push_back({glm::lookAt(glm::vec3(0, 50, 0), glm::vec3(0), glm::vec3(0, 0, -1)),
                         glm::ortho(-10.0f, 10.0f, -10.0f, 10.0f, 1.0f, 100.0f)});
  Camera camera;
  camera.position = {0, 10, 0};
  camera.target = {0, 0, 0};
  camera.up = {0, 0, -1};
  camera.fov_y_deg = 90.0f;
  const FrameView frame{camera.projection(1.0f) * camera.view(), {512, 512}};
  EXPECT_NEAR(aliasing_factor(setup, sun, 1024, frame, {0, 0, 0}, {0, 1, 0}), 0.5f, 0.005f);
  EXPECT_NEAR(aliasing_factor(setup, sun, 2048, frame, {0, 0, 0}, {0, 1, 0}), 0.25f, 0.0025f);
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
  const float psm = predicted_aliasing(perspective_shadow_map(camera, aspect, sun, scene_box(), 1024), sun, 1024, frame, ground, p95_fraction);
  const float uniform = predicted_aliasing(focused_uniform_map(camera, aspect, sun, scene_box(), 1024), sun, 1024, frame, ground, p95_fraction);
  EXPECT_GT(psm, 0.0f);
  EXPECT_LT(psm, uniform / 2.0f);
}

}  // namespace
}  // namespace shadow
