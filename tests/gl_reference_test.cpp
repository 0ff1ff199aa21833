// The exact reference (Embree rays to the light) against shadows computed from geometry on the
// floating-box scenes, and against shadow volumes, the exact GL method, on a scene of polygons.
#include "app/gl/context.hpp"
#include "app/render/renderer.hpp"
#include "app/scene/scene_file.hpp"
#include "floating_box.hpp"

#include <gtest/gtest.h>

#include <iostream>

namespace ecoview::test {
namespace {

class ReferenceOnFloatingBoxes : public testing::TestWithParam<shadow::LightType> {};

TEST_P(ReferenceOnFloatingBoxes, MatchesGeometryAwayFromEdges) {
  const auto context = create_headless_context("egl");
  pointgen::Random rng(70 + static_cast<int>(GetParam()));
  for (int i = 0; i < 4; ++i) {
    const FloatingBox s = random_floating_box(rng, GetParam());
    const Scene scene = s.scene();
    Renderer renderer(scene, {640, 480, 1024, shadow::Method::none});
    renderer.render(scene.camera, scene.lights[0]);
    const TruthComparison c = compare_with_truth(s, renderer.exact_visibility(), 2);
    std::cout << "case " << i << ": " << 100.0 * c.agreement() << " % of " << c.lit + c.shadowed << " plane pixels agree\n";
    EXPECT_GE(c.agreement(), 0.999) << "scene:\n" << s.scene_json();
    EXPECT_GE(c.shadowed_agreement(), 0.999) << "scene:\n" << s.scene_json();
    EXPECT_GE(c.shadowed, 300u) << "scene:\n" << s.scene_json();
  }
}

INSTANTIATE_TEST_SUITE_P(Lights, ReferenceOnFloatingBoxes,
                         testing::Values(shadow::LightType::directional, shadow::LightType::point, shadow::LightType::spot));

// Pixels showing a surface whose binary state (visibility < 0.5) the two images share.
double agreement(const Image8& a, const Image8& b, const Image<float>& depth) {
  std::size_t surface = 0, agreeing = 0;
  for (std::size_t i = 0; i < depth.samples.size(); ++i) {
    if (!(depth.samples[i] > 0.0f)) continue;
    ++surface;
    agreeing += (a.samples[i] < 128) == (b.samples[i] < 128);
  }
  return surface ? static_cast<double>(agreeing) / static_cast<double>(surface) : 0.0;
}

// Floating boxes are flat-shaded polygons only: the two exact methods must agree on every pixel
// but a few at the boxes' edges.
TEST(ReferenceAgainstVolumes, AgreesOnFloatingBoxesUnderEveryLight) {
  const auto context = create_headless_context("egl");
  pointgen::Random rng(90);
  for (const shadow::LightType type : {shadow::LightType::directional, shadow::LightType::point, shadow::LightType::spot}) {
    for (int i = 0; i < 3; ++i) {
      const FloatingBox s = random_floating_box(rng, type);
      const Scene scene = s.scene();
      Renderer renderer(scene, {640, 480, 1024, shadow::Method::volumes});
      renderer.render(scene.camera, scene.lights[0]);
      const double a = agreement(renderer.frame().read_visibility(), renderer.exact_visibility(), renderer.frame().read_depth());
      std::cout << "light " << static_cast<int>(type) << ", case " << i << ": " << 100.0 * a << " % of surface pixels agree\n";
      EXPECT_GE(a, 0.999) << "scene:\n" << s.scene_json();
    }
  }
}

// The courtyard under each of its lights drawn with `method`: the share of surface pixels whose
// shadow state agrees with the reference, per light.
std::vector<double> agreement_on_the_courtyard(shadow::Method method) {
  const Scene scene = load_scene(open_input("courtyard", "scenes"));
  Renderer renderer(scene, {640, 360, 1024, method});
  std::vector<double> per_light;
  for (const shadow::Light& light : scene.lights) {
    renderer.render(scene.camera, light);
    per_light.push_back(agreement(renderer.frame().read_visibility(), renderer.exact_visibility(), renderer.frame().read_depth()));
    std::cout << shadow::technique(method).name << ", light type " << static_cast<int>(light.type) << ": "
              << 100.0 * per_light.back() << " % of surface pixels agree\n";
  }
  return per_light;
}

// The courtyard adds a sphere and a knot with smooth normals: the reference takes the frame's
// shading normals for the side a surface turns to the light, so they agree there too.
TEST(ReferenceAgainstVolumes, AgreesOnTheCourtyardUnderEveryLight) {
  const auto context = create_headless_context("egl");
  for (double a : agreement_on_the_courtyard(shadow::Method::volumes)) EXPECT_GE(a, 0.999);
}

}  // namespace
}  // namespace ecoview::test
