// The warped, cascaded and paraboloid shadow maps (PSM, LiSPSM, cascades, DPSM, IPSM) against
// geometry the test computes itself: every ray from
// a visible receiver to the light, inside the scene, maps into the shadow map's clip cube with
// depth growing towards the receiver; the PSM's light cases follow the paper's geometric rule; no
// configuration, random or degenerate, gives NaN or infinity; a pushed PSM near plane refines the
// texels at its depth, and LiSPSM fades into the uniform map as the view turns parallel to the light.
#include "random_setups.hpp"
#include "shadow/aliasing.hpp"
#include "shadow/cascaded_map.hpp"
#include "shadow/focus_body.hpp"
#include "shadow/lispsm_map.hpp"
#include "shadow/paraboloid_map.hpp"
#include "shadow/post_perspective.hpp"
#include "shadow/psm_map.hpp"
#include "shadow/techniques.hpp"
#include "shadow/uniform_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace shadow {
namespace {

constexpr float aspect = 16.0f / 9.0f;

// A random point inside a convex body: a random mix of its vertices.
glm::vec3 random_point_in(const ConvexBody& body, pointgen::Random& rng) {
  const std::vector<glm::vec3> v = body.vertices();
  glm::vec3 sum(0.0f);
  float weights = 0.0f;
  for (const glm::vec3& p : v) {
    const float w = rng.uniform() * rng.uniform();
    sum += w * p;
    weights += w;
  }
  return sum / weights;
}

bool inside(const Box& box, const glm::vec3& p) {
  return glm::all(glm::greaterThanEqual(p, box.min)) && glm::all(glm::lessThanEqual(p, box.max));
}

bool lit_by_spot(const Light& light, const glm::vec3& p) {
  return light.type != LightType::spot || (glm::distance(p, light.position) > 0.01f &&
                                           glm::dot(glm::normalize(p - light.position), light.direction) >=
                                               std::cos(glm::radians(light.cone_deg)));
}

// Points from `receiver` towards the light, inside the scene: the casters that can shadow it.
std::vector<glm::vec3> ray_to_light(const glm::vec3& receiver, const Light& light, const Box& scene) {
  const glm::vec3 end = light.type == LightType::directional ? receiver - 400.0f * glm::normalize(light.direction)
                                                             : light.position;
  std::vector<glm::vec3> points;
  for (int i = 1; i <= 40; ++i) {
    const glm::vec3 p = glm::mix(receiver, end, static_cast<float>(i) / 41.0f);
    if (inside(scene, p)) points.push_back(p);
  }
  return points;
}

ShadowSetup psm(const Camera& c, const Light& l) { return perspective_shadow_map({c, aspect, l, scene_box(), 2048}); }
ShadowSetup lispsm(const Camera& c, const Light& l) { return light_space_perspective_map({c, aspect, l, scene_box(), 2048}); }
ShadowSetup cascades(const Camera& c, const Light& l) { return cascaded_map({c, aspect, l, scene_box(), 2048}); }
ShadowSetup dpsm(const Camera& c, const Light& l) { return dual_paraboloid_map({c, aspect, l, scene_box(), 2048}); }
ShadowSetup ipsm(const Camera& c, const Light& l) { return improved_paraboloid_map({c, aspect, l, scene_box(), 2048}); }

using Param = std::tuple<ShadowSetup (*)(const Camera&, const Light&), LightType>;

class WarpedMap : public testing::TestWithParam<Param> {};

TEST_P(WarpedMap, RaysFromReceiversToTheLightMapIntoTheCubeCastersFirst) {
  const auto [map, type] = GetParam();
  pointgen::Random rng(300 + static_cast<int>(type));
  int receivers = 0, casters = 0, warped = 0;
  for (int i = 0; i < 300; ++i) {
    const Camera camera = random_camera(rng);
    const Light light = random_light(rng, type);
    const FocusBodies bodies = focus_bodies(camera.projection(aspect) * camera.view(), light, scene_box());
    if (bodies.receivers.empty()) continue;
    const ShadowSetup setup = map(camera, light);
    const ShadowSetup uniform = focused_uniform_map({camera, aspect, light, scene_box(), 2048});
    warped += setup.views.size() != uniform.views.size() || setup.views[0].paraboloid ||
              setup.views[0].view_projection() != uniform.views[0].view_projection();
    for (int j = 0; j < 20; ++j) {
      const glm::vec3 r = random_point_in(bodies.receivers, rng);
      if (!lit_by_spot(light, r)) continue;
      const std::size_t layer = view_for(setup, light, r, 2048);
      const ShadowView& view = setup.views[layer];
      const glm::vec4 clip = view.clip(r);
      ASSERT_GT(clip.w, 0.0f) << "camera " << i;
      const glm::vec3 ndc = glm::vec3(clip) / clip.w;
      ASSERT_LE(glm::max(std::abs(ndc.x), glm::max(std::abs(ndc.y), std::abs(ndc.z))), 1.0001f) << "camera " << i;
      ++receivers;
      for (const glm::vec3& c : ray_to_light(r, light, scene_box())) {
        // A cube face holds only its own directions; a cascade must hold its receivers' casters.
        if (setup.selection == ViewSelection::cube_faces && view_for(setup, light, c, 2048) != layer) continue;
        const glm::vec4 cc = view.clip(c);
        ASSERT_GT(cc.w, 0.0f) << "camera " << i;
        const glm::vec3 cn = glm::vec3(cc) / cc.w;
        ASSERT_LE(glm::max(std::abs(cn.x), glm::max(std::abs(cn.y), std::abs(cn.z))), 1.0001f)
            << "camera " << i << ": caster at " << cn.x << ", " << cn.y << ", " << cn.z << ", its receiver at " << ndc.x
            << ", " << ndc.y << ", " << ndc.z;
        ASSERT_LE(cn.z, ndc.z + 1e-5f) << "a caster behind its receiver, camera " << i;
        ++casters;
      }
    }
  }
  EXPECT_GT(receivers, 2000);
  EXPECT_GT(casters, 10000);
  // Most maps are not the uniform fallback (LiSPSM and cascades take directional lights only,
  // the paraboloid maps point and spot lights only).
  const bool paraboloid = map == dpsm || map == ipsm;
  if (map == psm || (type == LightType::directional) != paraboloid) {
    EXPECT_GT(warped, 100);
  } else {
    EXPECT_EQ(warped, 0) << "the light this method does not warp should get the focused uniform map";
  }
}

INSTANTIATE_TEST_SUITE_P(MethodsAndLights, WarpedMap,
                         testing::Combine(testing::Values(&psm, &lispsm, &cascades, &dpsm, &ipsm),
                                          testing::Values(LightType::directional, LightType::point, LightType::spot)),
                         [](const testing::TestParamInfo<Param>& info) {
                           const LightType type = std::get<1>(info.param);
                           const auto map = std::get<0>(info.param);
                           return std::string(map == &psm      ? "psm_"
                                              : map == &lispsm   ? "lispsm_"
                                              : map == &cascades ? "cascades_"
                                              : map == &dpsm     ? "dpsm_"
                                                                 : "ipsm_") +
                                  (type == LightType::directional ? "directional" : type == LightType::point ? "point" : "spot");
                         });

// Seed 000, Sect. 3: a light in front of the viewer (a directional light shining towards it, a
// point light in front of the camera plane) stays a point light, one behind becomes inverted, and
// one in the camera plane (for a directional light: parallel to the image plane) directional.
TEST(PostPerspectiveLight, FollowsThePapersGeometricRule) {
  pointgen::Random rng(21);
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    const Camera camera = random_camera(rng);
    const glm::mat4 pps = camera.projection(aspect) * camera.view();
    const glm::vec3 forward = camera.forward();
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward);

    Light sun = random_light(rng, LightType::directional);
    const float from_front = glm::dot(-sun.direction, forward);
    if (std::abs(from_front) > 1e-2f) {
      EXPECT_EQ(post_perspective_light(pps, sun), from_front > 0 ? PostPerspectiveLight::point : PostPerspectiveLight::inverted);
      ++checked;
    }
    const float a = rng.uniform(0.0f, 6.2831853f);
    sun.direction = std::cos(a) * right + std::sin(a) * up;  // parallel to the image plane
    EXPECT_EQ(post_perspective_light(pps, sun), PostPerspectiveLight::directional);

    Light lamp = random_light(rng, LightType::point);
    const float ahead = glm::dot(lamp.position - camera.position, forward);
    if (std::abs(ahead) > 1e-2f) {
      EXPECT_EQ(post_perspective_light(pps, lamp), ahead > 0 ? PostPerspectiveLight::point : PostPerspectiveLight::inverted);
      ++checked;
    }
    lamp.position = camera.position + rng.uniform(-20, 20) * right + rng.uniform(-20, 20) * up;  // in the camera plane
    EXPECT_EQ(post_perspective_light(pps, lamp), PostPerspectiveLight::directional);
  }
  EXPECT_GT(checked, 3500);
}

// Seed 000, Sect. 3.3: a directional light perpendicular to the view is the best case. Near the
// eye the warped maps' texels on the ground must be far smaller than the uniform map's.
TEST(WarpedMap, NearTexelsAreSmallerThanTheUniformMapsForALightAcrossTheView) {
  const Camera camera = deep_view_camera();
  const Light sun{LightType::directional, {}, glm::normalize(glm::vec3(1, -1, 0)), 30};
  const glm::vec3 near_ground(0, 0, 40);
  const float psm = ground_texel_area(perspective_shadow_map({camera, aspect, sun, scene_box(), 1024}).views[0].view_projection(), near_ground);
  const float uniform = ground_texel_area(focused_uniform_map({camera, aspect, sun, scene_box(), 1024}).views[0].view_projection(), near_ground);
  const float lispsm = ground_texel_area(light_space_perspective_map({camera, aspect, sun, scene_box(), 1024}).views[0].view_projection(), near_ground);
  EXPECT_LT(psm, uniform / 16.0f);
  EXPECT_LT(lispsm, uniform / 4.0f);
}

// PSM, Stamminger and Drettakis 2002, Sect. 6: post-perspective depth is z_ndc = A - B n / z, so the depth range a
// ground element at depth z takes grows with the near plane n; for a light across the view the
// map resolves that depth, so pushing the near plane out to just before the point refines its
// texels.
TEST(PsmMap, PushedNearPlaneGivesFinerTexelsAtItsDepth) {
  const Camera camera = deep_view_camera();
  const Light sun{LightType::directional, {}, glm::normalize(glm::vec3(1, -1, 0)), 30};
  for (float z : {38.0f, 33.0f, 25.0f}) {  // ground straight ahead, some 7, 12 and 20 m away
    const glm::vec3 ground(0, 0, z);
    const float depth = glm::dot(ground - camera.position, camera.forward());
    const glm::mat4 unpushed = perspective_shadow_map({camera, aspect, sun, scene_box(), 1024, 0.0f}).views[0].view_projection();
    const glm::mat4 pushed = perspective_shadow_map({camera, aspect, sun, scene_box(), 1024, 0.9f * depth}).views[0].view_projection();
    EXPECT_LT(ground_texel_area(pushed, ground), ground_texel_area(unpushed, ground)) << "depth " << depth;
  }
}

// LiSPSM under a sun straight down, the camera tilted by gamma from straight down. A uniform
// (orthographic) map gives the ground the same texel area everywhere; the warp makes texels far
// ahead larger than near ones by a factor that falls to 1 as gamma does (its centre recedes as
// 1 / sin gamma). Below min_sin_gamma = 1e-3 the method returns the focused uniform map itself.

Camera tilted_down(float gamma) {
  Camera c = camera_looking({0, 30, 0}, {0, 30 - 30 * std::cos(gamma), -30 * std::sin(gamma)}, 0.5f, 200.0f);
  c.up = {0, 0, -1};
  return c;
}

const Light noon_sun{LightType::directional, {}, {0, -1, 0}, 30};

// Ground texel area 6 m beyond the ground point the camera looks at, over that 6 m before it.
float far_to_near_texel_area(float gamma) {
  const Camera camera = tilted_down(gamma);
  const glm::mat4 m = light_space_perspective_map({camera, aspect, noon_sun, scene_box(), 2048}).views[0].view_projection();
  const glm::vec3 looked_at(0, 0, -30 * std::tan(gamma));
  return ground_texel_area(m, looked_at + glm::vec3(0, 0, -6)) / ground_texel_area(m, looked_at + glm::vec3(0, 0, 6));
}

TEST(LispsmMap, WarpFadesIntoTheUniformMapAsTheViewTurnsParallelToTheLight) {
  float previous = INFINITY;
  for (float gamma : {0.5f, 0.1f, 0.02f, 0.002f}) {
    const float warp = far_to_near_texel_area(gamma) - 1.0f;
    EXPECT_GT(warp, 0.0f) << "gamma " << gamma;
    EXPECT_LT(warp, previous) << "gamma " << gamma;
    previous = warp;
  }
  EXPECT_GT(far_to_near_texel_area(0.5f), 1.2f);  // a real warp at 29°: near texels clearly finer
  EXPECT_LT(previous, 0.02f);  // at 0.1°: within 2% of uniform
}

TEST(LispsmMap, BelowMinSinGammaItIsTheUniformMapAboveItAWarp) {
  for (float sin_gamma : {5e-4f, 2e-3f}) {
    const Camera camera = tilted_down(std::asin(sin_gamma));
    const ShadowSetup lispsm = light_space_perspective_map({camera, aspect, noon_sun, scene_box(), 2048});
    const ShadowSetup uniform = focused_uniform_map({camera, aspect, noon_sun, scene_box(), 2048});
    ASSERT_EQ(lispsm.views.size(), 1u);
    const bool same = lispsm.views[0].view_projection() == uniform.views[0].view_projection();
    EXPECT_EQ(same, sin_gamma < 1e-3f) << "sin gamma " << sin_gamma << ": " << lispsm.description;
  }
}

// A setup the renderer can draw: at least one view, every matrix finite.
void expect_usable(const ShadowSetup& setup) {
  EXPECT_FALSE(setup.views.empty()) << setup.description;
  for (const ShadowView& v : setup.views) EXPECT_TRUE(finite(v)) << setup.description;
}

// Configurations where a warp breaks down, each with several cameras, for every method and the
// focused uniform map they fall back to: views with finite matrices.
TEST(WarpedMap, DegenerateConfigurationsGiveViewsWithFiniteMatrices) {
  Camera ahead;  // looking down -z
  ahead.position = glm::vec3(0, 10, 30);
  ahead.target = glm::vec3(0, 10, 0);
  Camera inside = ahead;  // inside the scene, near the ground
  inside.position = glm::vec3(3, 0.5f, 3);
  inside.target = glm::vec3(10, 0.5f, -10);
  Camera away = ahead;  // sees none of the scene
  away.position = glm::vec3(0, 10, 200);
  away.target = glm::vec3(0, 10, 400);
  away.far = 20.0f;
  Camera down = ahead;  // straight down with a sideways up
  down.target = glm::vec3(0, 0, 30);
  down.up = glm::vec3(0, 0, -1);
  std::vector<Light> lights;
  for (const glm::vec3& d : {glm::vec3(0, 0, -1), glm::vec3(0, 0, 1), glm::vec3(0, -1, 0), glm::vec3(1, 0, 0),
                             glm::vec3(0, 1, 0), glm::normalize(glm::vec3(0, -1e-7f, 1))}) {
    lights.push_back({LightType::directional, {}, d, 30});  // along, against, across, from below the view
  }
  for (const Camera& c : {ahead, inside, away, down}) {
    const glm::vec3 f = c.forward();
    for (const glm::vec3& p : {c.position, c.position + glm::vec3(5, 0, 0), c.position + 20.0f * f, c.position - 20.0f * f,
                               c.position + 1e-4f * f, c.position + glm::vec3(0, 500, 0), glm::vec3(0, 10, 0)}) {
      lights.push_back({LightType::point, p, {0, -1, 0}, 30});  // at the eye, in the camera plane, in view, behind
      lights.push_back({LightType::spot, p, f, 45});
      lights.push_back({LightType::spot, p, -f, 45});
    }
  }
  for (const Camera& c : {ahead, inside, away, down}) {
    for (const Light& light : lights) {
      for (float nearest : {0.0f, 5.0f, 1e6f}) {
        const ShadowInputs inputs(c, aspect, light, scene_box(), 1024, nearest);
        for (const Technique& t : techniques()) {
          if (t.setup) expect_usable(t.setup(inputs));
        }
      }
    }
  }
}

// A million random configurations for the PSM (ECOVIEW_PSM_CASES sets another), a tenth of that
// for every other method of the table, every kind of light: no setup without views, no NaN or
// infinity.
TEST(WarpedMap, AMillionRandomConfigurationsGiveFiniteMatrices) {
  const char* cases = std::getenv("ECOVIEW_PSM_CASES");
  const int count = cases ? std::atoi(cases) : 1000000;
  pointgen::Random rng(5);
  ASSERT_GT(count, 0);
  int bad = 0;
  auto count_bad = [&](const ShadowSetup& setup) {
    bad += setup.views.empty();
    for (const ShadowView& v : setup.views) bad += !finite(v);
  };
  for (int i = 0; i < count; ++i) {
    const Camera camera = random_camera(rng);
    const Light light = random_light(rng, static_cast<LightType>(i % 3));
    const ShadowInputs inputs(camera, aspect, light, scene_box(), 1024);
    count_bad(perspective_shadow_map(inputs));
    if (i % 10 != 0) continue;
    for (const Technique& t : techniques()) {
      if (t.setup && t.method != Method::psm) count_bad(t.setup(inputs));
    }
  }
  EXPECT_EQ(bad, 0);
}

}  // namespace
}  // namespace shadow
