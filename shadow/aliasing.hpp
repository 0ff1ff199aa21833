#pragma once
#include "shadow/light.hpp"
#include "shadow/shadow_setup.hpp"

#include <vector>

// The aliasing factor of docs/figures.md on the CPU, from a setup's matrices alone: what the frame's
// shader computes per pixel (shaders/lighting.glsl), for predicting a method's aliasing before it
// renders (`--method auto`).
namespace shadow {

// The view of `setup` whose map holds p's shadow, as the frame's shader picks it.
std::size_t view_for(const ShadowSetup& setup, const Light& light, const glm::vec3& p, int map_size);

// The camera side: its world → clip matrix and the frame's size in pixels.
struct FrameView {
  glm::mat4 view_projection{1.0f};
  glm::vec2 pixels{1.0f};
};

// The size in frame pixels of one shadow-map texel on the surface at p with normal n (the largest
// singular value of pixels per texel along the surface); a huge number where the light grazes it.
float aliasing_factor(const ShadowSetup& setup, const Light& light, int map_size, const FrameView& frame,
                      const glm::vec3& p, const glm::vec3& n);

struct SurfacePoint {
  glm::vec3 position;
  glm::vec3 normal;  // turned to the eye
};

// The value `fraction` of the way up some values in rank (0 for none).
float percentile(std::vector<float> values, float fraction);
// The fractions of alias_p95 (docs/figures.md) and of the median, which `--method auto` predicts.
constexpr float p95_fraction = 0.95f, median_fraction = 0.5f;

// A percentile (`fraction`) of the aliasing factor over surface points the light faces, predicted
// from the setup's matrices (0 when the light faces none).
float predicted_aliasing(const ShadowSetup& setup, const Light& light, int map_size, const FrameView& frame,
                         const std::vector<SurfacePoint>& surface, float fraction);

}  // namespace shadow
