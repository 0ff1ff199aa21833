#include "shadow/cascaded_map.hpp"

#include "shadow/focus_body.hpp"
#include "shadow/light_projection.hpp"
#include "shadow/uniform_map.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace shadow {
namespace {

// Weight of the logarithmic split against the uniform one.
constexpr float log_weight = 0.5f;

// The view depths bounding each slice, from the receivers' nearest to their farthest.
std::vector<float> split_depths(float near, float far, int cascades) {
  std::vector<float> splits;
  for (int i = 0; i <= cascades; ++i) {
    const float s = static_cast<float>(i) / static_cast<float>(cascades);
    splits.push_back(log_weight * near * std::pow(far / near, s) + (1.0f - log_weight) * (near + (far - near) * s));
  }
  return splits;
}

// One slice's map: an orthographic view around the sphere holding the slice, whose size does not
// change as the camera turns in place, its origin on whole texels. (The splits follow the
// receivers' depth range, so the sizes do change where that range does.)
ShadowView slice_map(const Camera& camera, float aspect, const Light& light, const Box& scene, float near, float far,
                     int map_size) {
  Camera slice = camera;
  slice.near = near;
  slice.far = far;
  const std::array<glm::vec3, 8> corners = frustum_corners(slice.projection(aspect) * slice.view());
  glm::vec3 centre(0.0f);
  for (const glm::vec3& c : corners) centre += c / 8.0f;
  float radius = 0.0f;
  for (const glm::vec3& c : corners) radius = std::max(radius, glm::distance(c, centre));
  // One texel more, for the snapping below, which moves the square by up to a texel.
  radius = std::max(radius * (1.0f + 2.0f / static_cast<float>(map_size)), 1e-3f);

  // A light frame that depends on the light alone, so texels keep their place from frame to frame.
  const glm::vec3 axis = glm::normalize(light.direction);
  glm::mat4 view = glm::lookAt(glm::vec3(0.0f), axis, light_up(axis, glm::vec3(0, 0, -1)));
  const float texel = 2.0f * radius / static_cast<float>(map_size);
  glm::vec3 c(view * glm::vec4(centre, 1.0f));
  c.x = std::floor(c.x / texel) * texel;
  c.y = std::floor(c.y / texel) * texel;

  // In depth: from the scene's point nearest the light, so that whatever the square holds has
  // all its casters in the map, to the far side of the sphere.
  float nearest = c.z + radius;
  for (int i = 0; i < 8; ++i) nearest = std::max(nearest, glm::vec3(view * glm::vec4(scene.corner(i), 1.0f)).z);
  const float farthest = c.z - radius;  // light space looks down -z
  const float pad = 1e-3f * (nearest - farthest) + 1e-4f;
  return {view, glm::ortho(c.x - radius, c.x + radius, c.y - radius, c.y + radius, -(nearest + pad), -(farthest - pad))};
}

}  // namespace

ShadowSetup cascaded_map(const ShadowInputs& in, int cascades) {
  const Camera& camera = in.camera;
  const FocusBodies& bodies = in.bodies;
  if (in.light.type != LightType::directional || bodies.receivers.empty()) return focused_uniform_map(in);
  float near = INFINITY, far = 0.0f;
  for (const glm::vec3& p : bodies.receivers.vertices()) {
    const float depth = glm::dot(p - camera.position, camera.forward());
    near = std::min(near, depth);
    far = std::max(far, depth);
  }
  near = std::max(near, camera.near);
  far = std::max(far, near * 1.001f);
  ShadowSetup setup{{}, ViewSelection::first_containing, "cascades"};
  const std::vector<float> splits = split_depths(near, far, cascades);
  for (int i = 0; i < cascades; ++i) {
    setup.views.push_back(slice_map(camera, in.aspect, in.light, in.scene, splits[static_cast<std::size_t>(i)],
                                    splits[static_cast<std::size_t>(i) + 1], in.map_size));
  }
  return setup;
}

}  // namespace shadow
