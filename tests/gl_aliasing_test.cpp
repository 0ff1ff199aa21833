// The aliasing factor against a case the test works out itself: a camera and a light both looking
// straight down on a plane, where a uniform map spreads its texels evenly over what the camera sees.
#include "app/bench/shadow_figures.hpp"
#include "app/gl/context.hpp"
#include "app/render/pixel_rays.hpp"
#include "app/render/renderer.hpp"
#include "app/scene/scene_file.hpp"
#include "shadow/aliasing.hpp"

#include <gtest/gtest.h>

namespace ecoview {
namespace {

constexpr int width = 640, height = 480, map_size = 256;

Scene plane_seen_from_above() {
  const std::string json = R"({"camera": {"position": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_y_deg": 60,
                                          "near": 0.5, "far": 50},
                               "lights": [{"type": "directional", "direction": [0, -1, 0]}],
                               "objects": [{"type": "plane", "center": [0, 0, 0], "size": [100, 100]}]})";
  return load_scene({"plane.json", json, [](const std::string&) { return std::nullopt; }});
}

TEST(AliasingFactor, IsTheUniformMapsTexelInPixelsOnAPlaneSeenFromAbove) {
  const auto context = create_headless_context("egl");
  const Scene scene = plane_seen_from_above();
  RenderSettings settings{width, height, map_size, shadow::Method::uniform};
  settings.aliasing = true;
  Renderer renderer(scene, settings);
  renderer.render(scene.camera, scene.lights[0]);
  const Image<float> aliasing = renderer.frame().read_aliasing();
  // The map's longer side spans the camera's wider footprint, `width` pixels, in `map_size` texels
  // (plus the fit's 1 % margin on either side): one texel is width / map_size pixels across.
  const double expected = 1.02 * width / map_size;
  for (const auto& [x, y] : {std::pair{width / 2, height / 2}, std::pair{10, 10}, std::pair{width - 10, height - 10}}) {
    EXPECT_NEAR(aliasing.at(x, y), expected, 0.01 * expected) << "pixel " << x << ", " << y;
  }
  EXPECT_NEAR(alias_percentile(aliasing, renderer.frame().read_visibility(), shadow::p95_fraction), expected, 0.01 * expected);
}

// --method auto's prediction on the GPU, for the same case: the median over the frame's surfaces.
TEST(PredictedAliasing, OnTheGpuIsTheUniformMapsTexelInPixelsOnAPlaneSeenFromAbove) {
  const auto context = create_headless_context("egl");
  const Scene scene = plane_seen_from_above();
  Renderer renderer(scene, RenderSettings{width, height, map_size, shadow::Method::uniform});
  renderer.render(scene.camera, scene.lights[0]);
  const double expected = 1.02 * width / map_size;
  const std::vector<float> predicted = renderer.frame().predict_aliasing(scene.camera, scene.camera, scene.lights[0],
                                                                         {renderer.shadow_setup()}, map_size, shadow::median_fraction);
  ASSERT_EQ(predicted.size(), 1u);
  EXPECT_NEAR(predicted[0], expected, 0.01 * expected);
  // A map of twice the texels each way has texels half as large.
  EXPECT_NEAR(renderer.frame().predict_aliasing(scene.camera, scene.camera, scene.lights[0], {renderer.shadow_setup()}, 2 * map_size,
                                                shadow::median_fraction)[0], expected / 2, 0.01 * expected);
}

TEST(AliasingFactor, IsZeroWithoutAShadowMapAndNegativeWhereNothingIsDrawn) {
  const auto context = create_headless_context("egl");
  Scene scene = plane_seen_from_above();
  RenderSettings settings{width, height, map_size, shadow::Method::none};
  settings.aliasing = true;
  Renderer renderer(scene, settings);
  renderer.render(scene.camera, scene.lights[0]);
  EXPECT_EQ(renderer.frame().read_aliasing().at(width / 2, height / 2), 0.0f);
  scene.camera.target = glm::vec3(0, 20, 0);  // looking up into the sky
  scene.camera.up = glm::vec3(0, 0, 1);
  renderer.render(scene.camera, scene.lights[0]);
  EXPECT_LT(renderer.frame().read_aliasing().at(width / 2, height / 2), 0.0f);
}

// The aliasing factor predicted from a setup's matrices and the frame's surface, on the CPU and on
// the GPU, against the aliasing AOV the frame shader computed, on the deep field under a light across the view: its
// median (what --method auto chooses by) and its 95th percentile (alias_p95).
TEST(PredictedAliasing, MatchesTheFramesMedianAndAliasP95) {
  const auto context = create_headless_context("egl");
  const Scene scene = load_scene(open_input("field", "scenes"));
  const shadow::Light& light = scene.lights[6];
  for (shadow::Method method : {shadow::Method::uniform, shadow::Method::psm, shadow::Method::lispsm, shadow::Method::cascades}) {
    RenderSettings settings{width, height, 1024, method};
    settings.aliasing = true;
    Renderer renderer(scene, settings);
    renderer.render(scene.camera, light);
    const Image<float> depth = renderer.frame().read_depth();
    const shadow::FrameView frame{scene.camera.projection(static_cast<float>(width) / height) * scene.camera.view(),
                                  glm::vec2(width, height)};
    const std::vector<shadow::SurfacePoint> surface = surface_points(depth, PixelRays(scene.camera, width, height), 8);
    for (float fraction : {shadow::median_fraction, shadow::p95_fraction}) {
      const float predicted = shadow::predicted_aliasing(renderer.shadow_setup(), light, 1024, frame, surface, fraction);
      const double measured = alias_percentile(renderer.frame().read_aliasing(), renderer.frame().read_visibility(), fraction);
      EXPECT_NEAR(predicted, measured, 0.15 * measured) << shadow::technique(method).name << ", percentile " << fraction;
      // On the GPU, from the frame's own normals rather than ones rebuilt from its depth.
      const float on_gpu = renderer.frame().predict_aliasing(scene.camera, scene.camera, light, {renderer.shadow_setup()}, 1024, fraction)[0];
      EXPECT_NEAR(on_gpu, predicted, 0.05 * predicted) << shadow::technique(method).name << ", percentile " << fraction << " on the GPU";
    }
  }
}

}  // namespace
}  // namespace ecoview
