// Focus bodies and the focused uniform map, over many random cameras and lights: every receiver
// the camera sees must land inside the map that holds its shadow, the map is tight around them,
// and a lamp among them gets cube faces.
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
    const ShadowSetup setup = focused_uniform_map({camera, aspect, light, scene_box(), 2048});
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
    const glm::mat4 m = focused_uniform_map({camera, aspect, light, scene_box(), 2048}).views[0].view_projection();
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

// The map a virtual paged map is cut from depends on the light and the scene alone: two random
// cameras get the same views, and every corner of the lit scene lands inside its view's clip cube.
TEST(LitSceneMap, IsTheSameForEveryCameraAndHoldsAllTheLitScene) {
  pointgen::Random rng(11);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const LightType type = i % 3 == 0 ? LightType::directional : i % 3 == 1 ? LightType::spot : LightType::point;
    const Light light = random_light(rng, type);
    const ShadowSetup one = lit_scene_map({random_camera(rng), 1.5f, light, scene_box(), 1024});
    const ShadowSetup other = lit_scene_map({random_camera(rng), 0.8f, light, scene_box(), 1024});
    ASSERT_EQ(one.views.size(), other.views.size());
    for (std::size_t v = 0; v < one.views.size(); ++v) {
      ASSERT_TRUE(finite(one.views[v].view_projection()));
      EXPECT_EQ(one.views[v].view_projection(), other.views[v].view_projection()) << "light " << i << ", view " << v;
    }
    for (const glm::vec3& p : or_scene({}, light, scene_box()).receivers.vertices()) {
      if (type != LightType::directional && glm::distance(p, light.position) < 0.01f) continue;  // the apex: no direction
      if (type == LightType::spot &&
          glm::dot(glm::normalize(p - light.position), light.direction) < std::cos(glm::radians(light.cone_deg))) {
        continue;  // in the light's square pyramid, outside its cone: unlit
      }
      const glm::vec4 clip = one.views[view_for(one, light, p, 1024)].view_projection() * glm::vec4(p, 1.0f);
      ASSERT_GT(clip.w, 0.0f) << "light " << i;
      EXPECT_LE(glm::max(std::abs(clip.x), std::abs(clip.y)) / clip.w, 1.0001f) << "light " << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

constexpr float wide = 16.0f / 9.0f;

// The focused uniform map is fitted to the receivers (with 1% padding), not to the scene: their
// extreme points reach nearly to the map's edge (1 / 1.02) on both sides of both axes, and none
// lies beyond. (Not spot lights: their map is clamped to the cone, which cuts off receivers in the
// corners of the light's square pyramid.)
TEST(FocusedMapFit, ReceiversReachTheMapsEdgesAndStayInside) {
  pointgen::Random rng(500);
  int directional = 0, point = 0;  // setups checked
  for (int i = 0; i < 600; ++i) {
    const Camera camera = random_camera(rng);
    const Light light = random_light(rng, i % 2 ? LightType::point : LightType::directional);
    const FocusBodies bodies = focus_bodies(camera.projection(wide) * camera.view(), light, scene_box());
    if (bodies.receivers.empty()) continue;
    const ShadowSetup setup = focused_uniform_map({camera, wide, light, scene_box(), 2048});
    if (setup.selection != ViewSelection::single) continue;  // cube faces have fixed 90° sides
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : bodies.receivers.vertices()) {
      const glm::vec2 q(ndc(setup.views[0].view_projection(), p));
      lo = glm::min(lo, q);
      hi = glm::max(hi, q);
    }
    EXPECT_GE(glm::min(lo.x, lo.y), -1.0001f) << "camera " << i;
    EXPECT_LE(glm::max(hi.x, hi.y), 1.0001f) << "camera " << i;
    EXPECT_LE(glm::max(lo.x, lo.y), -0.95f) << "camera " << i << ": map not tight";
    EXPECT_GE(glm::min(hi.x, hi.y), 0.95f) << "camera " << i << ": map not tight";
    ++(light.type == LightType::point ? point : directional);
  }
  EXPECT_GT(directional, 150);
  EXPECT_GT(point, 100);  // with one map
}

// A point light inside the receivers (V ∩ S) sees them in every direction: no single frustum
// holds them, so it gets the six cube faces. A lamp from which every corner of the view frustum
// (and so every receiver) lies within 30° of one axis is served by one map (limit 60°).
TEST(FocusedMapPointLight, LampAmongReceiversGetsACubeDistantLampOneMap) {
  const Camera overview = camera_looking({0, 15, 45}, {0, 0, 0}, 0.5f, 200.0f);
  const Light middle{LightType::point, {0, 5, 0}, {0, -1, 0}, 30};
  const glm::mat4 vp = overview.projection(wide) * overview.view();
  const glm::vec3 lamp_ndc = ndc(vp, middle.position);
  ASSERT_LT(glm::max(std::abs(lamp_ndc.x), glm::max(std::abs(lamp_ndc.y), std::abs(lamp_ndc.z))), 1.0f);  // in V
  const ShadowSetup cube = focused_uniform_map({overview, wide, middle, scene_box(), 1024});
  EXPECT_EQ(cube.selection, ViewSelection::cube_faces);
  EXPECT_EQ(cube.views.size(), 6u);

  const Camera close_up = camera_looking({0, 3, 10}, {0, 0, 0}, 0.5f, 20.0f);
  const Light high{LightType::point, {0, 300, 0}, {0, -1, 0}, 30};
  const glm::vec3 axis = glm::normalize(close_up.target - high.position);
  const glm::mat4 inverse = glm::inverse(close_up.projection(wide) * close_up.view());
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 c = inverse * glm::vec4(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1, 1);
    ASSERT_GT(glm::dot(glm::normalize(glm::vec3(c) / c.w - high.position), axis), std::cos(glm::radians(30.0f)));
  }
  const ShadowSetup single = focused_uniform_map({close_up, wide, high, scene_box(), 1024});
  EXPECT_EQ(single.selection, ViewSelection::single);
  EXPECT_EQ(single.views.size(), 1u);
}

}  // namespace
}  // namespace shadow
