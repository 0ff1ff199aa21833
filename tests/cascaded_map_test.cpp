// The cascaded map against geometry the test works out itself: the slices follow the practical
// split scheme, the maps snap to whole texels as the camera moves, keep their texel sizes as it
// turns, and grow coarser with the cascade index.
#include "random_setups.hpp"
#include "shadow/cascaded_map.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace shadow {
namespace {

constexpr float aspect = 16.0f / 9.0f;

// Cascades. A camera inside a scene far larger than its frustum sees receivers over exactly its
// near..far depth range, so the slices are known: the practical split scheme (Zhang et al. 2006)
//   C_i = λ n (f/n)^(i/m) + (1 - λ) (n + (f - n) i/m),  λ = 1/2.
// The sphere around the slice [a, b] is centred on the view axis at depth (a + b)/2 with radius
// sqrt(((b - a)/2)^2 + b^2 (tx^2 + ty^2)) (its far corners; tx, ty the half-angle tangents), and
// each map is that sphere's square, one texel wider each side, its centre snapped down to texels.

constexpr int cascade_map_size = 512;

Box huge_scene() {
  Box b;
  b.add(glm::vec3(-1000.0f));
  b.add(glm::vec3(1000.0f));
  return b;
}

const Light across_sun{LightType::directional, {}, glm::normalize(glm::vec3(1, -1, 0)), 30};

ShadowSetup cascades_for(const Camera& camera) {
  return cascaded_map({camera, aspect, across_sun, huge_scene(), cascade_map_size}, 4);
}

// Half the side of a cascade's square in metres (an orthographic projection's 1 / m[0][0]).
float half_side(const ShadowView& v) { return 1.0f / v.projection[0][0]; }
float texel_size(const ShadowView& v) { return 2.0f * half_side(v) / cascade_map_size; }
glm::vec2 texel_coordinates(const ShadowView& v, const glm::vec3& p) {
  return (glm::vec2(ndc(v.view_projection(), p)) + 1.0f) * 0.5f * static_cast<float>(cascade_map_size);
}

const Camera cascade_camera = camera_looking({3, 2, 5}, {3, 1, -40}, 0.5f, 100.0f);

TEST(CascadedMap, SlicesFollowThePracticalSplitScheme) {
  const Camera& camera = cascade_camera;
  const ShadowSetup setup = cascades_for(camera);
  ASSERT_EQ(setup.selection, ViewSelection::first_containing);
  ASSERT_EQ(setup.views.size(), 4u);
  const float n = camera.near, f = camera.far, ty = std::tan(glm::radians(camera.fov_y_deg) / 2), tx = ty * aspect;
  auto split = [&](int i) { return 0.5f * n * std::pow(f / n, i / 4.0f) + 0.5f * (n + (f - n) * i / 4.0f); };
  for (int i = 0; i < 4; ++i) {
    const float a = split(i), b = split(i + 1);
    const float radius = std::sqrt((b - a) * (b - a) / 4 + b * b * (tx * tx + ty * ty));
    const ShadowView& v = setup.views[static_cast<std::size_t>(i)];
    EXPECT_NEAR(half_side(v), radius * (1.0f + 2.0f / cascade_map_size), 1e-4f * radius) << "cascade " << i;
    // The square's centre in light space: the sphere's centre, snapped down by less than a texel.
    const glm::vec2 centre(v.view * glm::vec4(camera.position + 0.5f * (a + b) * camera.forward(), 1.0f));
    const glm::vec2 square(-v.projection[3][0] / v.projection[0][0], -v.projection[3][1] / v.projection[1][1]);
    const glm::vec2 snapped_by = centre - square;
    const float tolerance = 1e-3f * texel_size(v);
    EXPECT_GE(glm::min(snapped_by.x, snapped_by.y), -tolerance) << "cascade " << i;
    EXPECT_LE(glm::max(snapped_by.x, snapped_by.y), texel_size(v) + tolerance) << "cascade " << i;
  }
}

// Moving sideways by a fraction of the finest texel must shift each map by whole texels (or not at
// all): a fixed world point's texel coordinates change by whole numbers. An unsnapped map would
// shift them by the fraction. Over 8 steps the grids must also follow the camera somewhere.
TEST(CascadedMap, MovingSidewaysKeepsTheTexelGrid) {
  const ShadowSetup start = cascades_for(cascade_camera);
  const float step = 0.37f * texel_size(start.views[0]);
  const glm::vec3 right = glm::normalize(glm::cross(cascade_camera.forward(), cascade_camera.up));
  int whole_moves = 0;
  for (int k = 1; k <= 8; ++k) {
    Camera moved = cascade_camera;
    moved.position += static_cast<float>(k) * step * right;
    moved.target += static_cast<float>(k) * step * right;
    const ShadowSetup after = cascades_for(moved);
    ASSERT_EQ(after.views.size(), start.views.size());
    for (std::size_t i = 0; i < start.views.size(); ++i) {
      // A world point near the cascade's centre (small coordinates: little rounding).
      const glm::vec3 p(glm::inverse(start.views[i].view_projection()) * glm::vec4(0.1f, -0.2f, 0.0f, 1.0f));
      const glm::vec2 shift = texel_coordinates(after.views[i], p) - texel_coordinates(start.views[i], p);
      EXPECT_NEAR(shift.x, std::round(shift.x), 1e-3f) << "cascade " << i << ", step " << k;
      EXPECT_NEAR(shift.y, std::round(shift.y), 1e-3f) << "cascade " << i << ", step " << k;
      whole_moves += std::round(shift.x) != 0.0f || std::round(shift.y) != 0.0f;
    }
  }
  EXPECT_GT(whole_moves, 0);
}

// A slice's bounding sphere does not depend on where the camera looks, so turning in place must
// keep every cascade's texel size.
TEST(CascadedMap, TurningInPlaceKeepsTexelSizes) {
  const ShadowSetup start = cascades_for(cascade_camera);
  for (const glm::vec3& direction : {glm::vec3(1, 0, -1), glm::vec3(1, 0, 0), glm::vec3(-2, -1, 1), glm::vec3(0.3f, 0.5f, 1)}) {
    Camera turned = cascade_camera;
    turned.target = turned.position + 10.0f * glm::normalize(direction);
    const ShadowSetup after = cascades_for(turned);
    ASSERT_EQ(after.views.size(), start.views.size());
    for (std::size_t i = 0; i < start.views.size(); ++i) {
      EXPECT_NEAR(texel_size(after.views[i]), texel_size(start.views[i]), 1e-4f * texel_size(start.views[i])) << "cascade " << i;
      EXPECT_FLOAT_EQ(after.views[i].projection[1][1], after.views[i].projection[0][0]);  // square texels
    }
  }
}

// Both the far depth and the depth span of the slices grow with the index (the uniform part's
// span is constant, the logarithmic part's grows), so their spheres and texels grow too.
TEST(CascadedMap, TexelsGrowWithCascadeIndex) {
  pointgen::Random rng(501);
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    const Camera camera = random_camera(rng);
    const Light light = random_light(rng, LightType::directional);
    const ShadowSetup setup = cascaded_map({camera, aspect, light, scene_box(), 1024});
    if (setup.selection != ViewSelection::first_containing) continue;
    for (std::size_t c = 1; c < setup.views.size(); ++c) {
      EXPECT_GT(half_side(setup.views[c]), half_side(setup.views[c - 1])) << "camera " << i << ", cascade " << c;
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);
}

}  // namespace
}  // namespace shadow
