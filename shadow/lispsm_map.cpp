#include "shadow/lispsm_map.hpp"

#include "shadow/focus_body.hpp"
#include "shadow/light_projection.hpp"
#include "shadow/post_perspective.hpp"
#include "shadow/uniform_map.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace shadow {
namespace {

// Below this sine of the angle between view and light the warp would have no axis.
constexpr float min_sin_gamma = 1e-3f;

}  // namespace

ShadowSetup light_space_perspective_map(const ShadowInputs& in) {
  const Camera& camera = in.camera;
  const Light& light = in.light;
  const FocusBodies& bodies = in.bodies;
  if (light.type != LightType::directional || bodies.receivers.empty()) return focused_uniform_map(in);
  const glm::vec3 d = glm::normalize(light.direction), f = camera.forward();
  const glm::vec3 across = f - glm::dot(f, d) * d;  // the view direction perpendicular to the light
  const float sin_gamma = glm::length(across);
  if (sin_gamma < min_sin_gamma) return focused_uniform_map(in);
  const glm::vec3 axis = across / sin_gamma;

  // The casters' extent along the warp axis; the receivers' view depth (Wimmer's z_n, z_f).
  float a_min = INFINITY, a_max = -INFINITY, z_near = INFINITY, z_far = -INFINITY;
  for (const glm::vec3& p : bodies.casters.vertices()) {
    a_min = std::min(a_min, glm::dot(p, axis));
    a_max = std::max(a_max, glm::dot(p, axis));
  }
  for (const glm::vec3& p : bodies.receivers.vertices()) {
    z_near = std::min(z_near, glm::dot(p - camera.position, f));
    z_far = std::max(z_far, glm::dot(p - camera.position, f));
  }
  z_near = std::max(z_near, camera.near);
  z_far = std::max(z_far, z_near);
  // Wimmer's optimal distance of the warp centre before the casters: it spreads the aliasing
  // evenly over the view depth.
  const float n = (z_near + std::sqrt(z_near * z_far)) / sin_gamma;
  const glm::vec3 centre = camera.position + (a_min - n - glm::dot(camera.position, axis)) * axis;
  const float depth = std::max(a_max - a_min, 1e-4f * n);
  const glm::mat4 warp = glm::perspective(glm::radians(90.0f), 1.0f, n, n + depth) * glm::lookAt(centre, centre + axis, d);

  const FocusBodies warped{bodies.receivers.transformed(warp), bodies.casters.transformed(warp)};
  // The warp looks down +z in its post-perspective space; the light stays at infinity there.
  if (const std::optional<ShadowView> view = fit_light_view(warp * homogeneous(light), warped, {0, 0, 1})) {
    return {{ShadowView{view->view * warp, view->projection}}, ViewSelection::single, "lispsm"};
  }
  return focused_uniform_map(in);
}

}  // namespace shadow
