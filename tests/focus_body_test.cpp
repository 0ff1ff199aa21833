// Focus bodies and the focused uniform map, over many random cameras and lights: every receiver
// the camera sees must land inside the map that holds its shadow, and no configuration may give
// a matrix with NaN or infinity.
#include "random_setups.hpp"
#include "shadow/aliasing.hpp"
#include "shadow/focus_body.hpp"
#include "shadow/uniform_map.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace shadow {
namespace {

class FocusedMap : public testing::TestWithParam<LightType> {};

TEST_P(FocusedMap, EveryReceiverLandsInsideItsMapsClipCube) {
  pointgen::Random rng(100 + static_cast<int>(GetParam()));
  const float aspect = 16.0f / 9.0f;
  int checked = 0;
  for (int i = 0; i < 400; ++i) {
    const Camera camera = random_camera(rng);
    const Light light = random_light(rng, GetParam());
    const FocusBodies bodies = focus_bodies(camera.projection(aspect) * camera.view(), light, scene_box());
    if (bodies.receivers.empty()) continue;
    const ShadowSetup setup = focused_uniform_map(camera, aspect, light, scene_box(), 2048);
    for (const ShadowView& v : setup.views) ASSERT_TRUE(finite(v.view_projection()));
    for (const glm::vec3& p : bodies.receivers.vertices()) {
      const glm::vec4 clip = setup.views[view_for(setup, light, p, 2048)].view_projection() * glm::vec4(p, 1.0f);
      // A point light's single map covers receivers within 60° of its axis; wider spreads get a cube.
      ASSERT_GT(clip.w, 0.0f);
      const glm::vec3 ndc = glm::vec3(clip) / clip.w;
      EXPECT_LE(std::abs(ndc.x), 1.0001f) << "camera " << i;
      EXPECT_LE(std::abs(ndc.y), 1.0001f) << "camera " << i;
      EXPECT_LE(std::abs(ndc.z), 1.0001f) << "camera " << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

INSTANTIATE_TEST_SUITE_P(Lights, FocusedMap, testing::Values(LightType::directional, LightType::point),
                         [](const auto& info) { return info.param == LightType::directional ? std::string("directional")
                                                                                            : std::string("point"); });

TEST(FocusedMap, SpotReceiversInsideTheConeLandInsideTheMap) {
  int checked = 0;
  pointgen::Random rng(7);
  const float aspect = 1.5f;
  for (int i = 0; i < 400; ++i) {
    const Camera camera = random_camera(rng);
    Light light = random_light(rng, LightType::spot);
    light.direction = glm::normalize(glm::vec3(rng.uniform(-0.5f, 0.5f), -1.0f, rng.uniform(-0.5f, 0.5f)));
    const FocusBodies bodies = focus_bodies(camera.projection(aspect) * camera.view(), light, scene_box());
    if (bodies.receivers.empty()) continue;
    const glm::mat4 m = focused_uniform_map(camera, aspect, light, scene_box(), 2048).views[0].view_projection();
    for (const glm::vec3& p : bodies.receivers.vertices()) {
      // L is the square pyramid around the cone; what lies outside the cone gets no light anyway,
      // and the pyramid's apex (the light itself) has no direction.
      if (glm::distance(p, light.position) < 0.01f ||
          glm::dot(glm::normalize(p - light.position), light.direction) < std::cos(glm::radians(light.cone_deg))) {
        continue;
      }
      const glm::vec4 clip = m * glm::vec4(p, 1.0f);
      ASSERT_GT(clip.w, 0.0f);
      EXPECT_LE(glm::max(std::abs(clip.x), std::abs(clip.y)) / clip.w, 1.0001f) << "camera " << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace shadow
