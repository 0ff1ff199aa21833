#pragma once
#include "app/render/image.hpp"
#include "app/scene/scene.hpp"
#include "pointgen/random.hpp"
#include "shadow/camera.hpp"
#include "shadow/light.hpp"

#include <string>

// A box floating over a ground plane under one light, and the shadow the plane must show, computed
// from geometry alone (rays against the box), to check rendered `shadow` AOVs against.
namespace ecoview::test {

struct FloatingBox {
  glm::vec3 box_min, box_max;
  float plane_half_size = 20.0f;  // the plane is [-h, h]^2 at y = 0
  shadow::Light light;
  shadow::Camera camera;

  std::string scene_json() const;
  // That scene, as a scene file named floating_box.json loads it.
  Scene scene() const;
};

// A random configuration whose shadow falls on the plane in view.
FloatingBox random_floating_box(pointgen::Random& rng, shadow::LightType type);

// Plane pixels away from shadow and silhouette edges, by their geometric truth.
struct TruthComparison {
  std::size_t lit = 0, lit_agreeing = 0;
  std::size_t shadowed = 0, shadowed_agreeing = 0;

  static double ratio(std::size_t a, std::size_t b) { return b ? static_cast<double>(a) / static_cast<double>(b) : 0.0; }
  double agreement() const { return ratio(lit_agreeing + shadowed_agreeing, lit + shadowed); }
  double lit_agreement() const { return ratio(lit_agreeing, lit); }
  double shadowed_agreement() const { return ratio(shadowed_agreeing, shadowed); }
  // For looking at failures: gray where compared and agreeing, red where the geometry says
  // shadowed but the frame is lit, blue the other way round, black where not compared.
  Image8 mismatches;
};

// Compares the binary state (visibility < 0.5) of each plane pixel in a `shadow` AOV with the
// geometric truth, skipping pixels within `margin` pixels of a change in the truth or of a pixel
// that does not show the plane.
TruthComparison compare_with_truth(const FloatingBox& scene, const Image8& shadow_aov, int margin);

}  // namespace ecoview::test
