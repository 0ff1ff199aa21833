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

TEST(FocusedMap, DegenerateConfigurationsGiveFiniteMatrices) {
  Camera camera;
  camera.position = glm::vec3(0, 10, 30);
  camera.target = glm::vec3(0, 10, 0);  // looking down -Z
  const Box scene = scene_box();
  std::vector<Light> lights;
  for (const glm::vec3& d : {glm::vec3(0, 0, -1), glm::vec3(0, 0, 1), glm::vec3(0, -1, 0), glm::vec3(1, 0, 0)}) {
    lights.push_back({LightType::directional, {}, d, 30});  // along, against, across the view
  }
  for (const glm::vec3& p : {camera.position, glm::vec3(5, 10, 30), glm::vec3(0, 10, 0), glm::vec3(0, 10, 500)}) {
    lights.push_back({LightType::point, p, {0, -1, 0}, 30});  // at the eye, in the camera plane, in view, far behind
    lights.push_back({LightType::spot, p, {0, 0, -1}, 45});
  }
  Camera away = camera;
  away.target = glm::vec3(0, 10, 100);  // looking away from the scene box's contents beyond far
  away.far = 20.0f;
  away.position = glm::vec3(0, 10, 200);
  for (const Camera& c : {camera, away}) {
    for (const Light& light : lights) {
      for (const ShadowView& v : focused_uniform_map(c, 1.0f, light, scene, 1024).views) {
        EXPECT_TRUE(finite(v.view_projection()));
      }
    }
  }
}

}  // namespace
}  // namespace shadow
