// Paraboloid maps (DPSM, IPSM) against geometry the test computes itself: the projection puts the
// cone of half-angle 2 atan(zoom) on the unit circle with depth linear in distance; IPSM cuts the
// paraboloid to narrow cones and falls back to two hemispheres when the light is among the
// receivers; the culling frusta hold whatever a view maps into its disc.
#include "random_setups.hpp"
#include "shadow/paraboloid_map.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace shadow {
namespace {

constexpr float aspect = 16.0f / 9.0f;

TEST(Paraboloid, MapsItsConeOntoTheUnitCircleWithDepthLinearInDistance) {
  pointgen::Random rng(40);
  for (int i = 0; i < 1000; ++i) {
    const glm::vec3 light(rng.uniform(-10, 10), rng.uniform(0, 10), rng.uniform(-10, 10));
    const glm::vec3 axis = random_unit(rng);
    const Paraboloid p{rng.uniform(0.05f, 1.2f), rng.uniform(5, 100)};
    const glm::vec3 up = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const ShadowView view(glm::lookAt(light, light + axis, up), p);
    // A direction on the cone's rim, at a random distance within the range.
    const float half_angle = 2.0f * std::atan(p.zoom);
    const glm::vec3 side = glm::normalize(glm::cross(axis, random_unit(rng)));
    const glm::vec3 rim = std::cos(half_angle) * axis + std::sin(half_angle) * side;
    const float distance = rng.uniform(0.0f, p.range);
    const glm::vec4 clip = view.clip(light + distance * rim);
    ASSERT_GT(clip.w, 0.0f);
    EXPECT_NEAR(glm::length(glm::vec2(clip) / clip.w), 1.0f, 1e-3f);
    EXPECT_NEAR(clip.z / clip.w, 2.0f * distance / p.range - 1.0f, 1e-4f);
    const glm::vec4 centre = view.clip(light + distance * axis);
    EXPECT_NEAR(glm::length(glm::vec2(centre) / centre.w), 0.0f, 1e-5f);
  }
}

Camera camera_at(const glm::vec3& position, const glm::vec3& target) {
  Camera c;
  c.position = position;
  c.target = target;
  c.near = 0.5f;
  c.far = 60.0f;
  return c;
}

TEST(ImprovedParaboloid, CutsTheParaboloidToADistantViewAndFallsBackToTwoWhereTheLightIsInView) {
  const Light lamp{LightType::point, {0, 40, -90}, {0, -1, 0}, 30};
  const Camera far_view = camera_at({0, 3, 40}, {0, 0, 0});
  const ShadowSetup ipsm = improved_paraboloid_map({far_view, aspect, lamp, scene_box(), 2048});
  const ShadowSetup dpsm = dual_paraboloid_map({far_view, aspect, lamp, scene_box(), 2048});
  ASSERT_EQ(ipsm.views.size(), 1u);
  ASSERT_EQ(dpsm.views.size(), 2u);
  ASSERT_TRUE(ipsm.views[0].paraboloid && dpsm.views[0].paraboloid);
  // Texels along the axis span 4 zoom / size radians: the cut map's are at least 3x finer.
  EXPECT_LT(ipsm.views[0].paraboloid->zoom, dpsm.views[0].paraboloid->zoom / 3.0f);

  const Camera around_the_lamp = camera_at({0, 8, -10}, {0, 10, -45});
  EXPECT_EQ(improved_paraboloid_map({around_the_lamp, aspect, {LightType::point, {0, 10, -30}, {0, -1, 0}, 30}, scene_box(), 2048}).selection,
            ViewSelection::hemispheres);
}

TEST(Paraboloid, EnclosingFrustaHoldWhatTheViewMapsIntoItsDisc) {
  pointgen::Random rng(41);
  int checked = 0, in_pyramids = 0;  // the second: points of views culled by one pyramid
  for (int i = 0; i < 200; ++i) {
    const Camera camera = random_camera(rng);
    const Light light = random_light(rng, i % 2 ? LightType::point : LightType::spot);
    for (const ShadowSetup& setup : {dual_paraboloid_map({camera, aspect, light, scene_box(), 1024}),
                                     improved_paraboloid_map({camera, aspect, light, scene_box(), 1024})}) {
      for (const ShadowView& view : setup.views) {
        const std::vector<glm::mat4> frusta = enclosing_frusta(view);
        for (int j = 0; j < 50; ++j) {
          const glm::vec3 p = light.position + rng.uniform(0.01f, 0.99f) * view.paraboloid->range * random_unit(rng);
          const glm::vec4 clip = view.clip(p);
          // The map's disc: its corners hold directions outside the cone, which no lookup uses.
          if (!(clip.w > 0.0f) || glm::length(glm::vec2(clip)) > clip.w) continue;
          bool inside = false;
          for (const glm::mat4& m : frusta) {
            const glm::vec4 c = m * glm::vec4(p, 1.0f);
            inside = inside || (c.w > 0.0f && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w && std::abs(c.z) <= c.w);
          }
          EXPECT_TRUE(inside) << "a mapped point outside every culling frustum";
          ++checked;
          in_pyramids += frusta.size() == 1;
        }
      }
    }
  }
  EXPECT_GT(checked, 5000);
  EXPECT_GT(in_pyramids, 1000);
}

}  // namespace
}  // namespace shadow
