#include "shadow/post_perspective.hpp"

#include <algorithm>
#include <cmath>

namespace shadow {
namespace {

// A post-perspective light farther than 1 / at_infinity from the origin (the unit cube spans 2)
// counts as directional.
constexpr float at_infinity = 1e-4f;

}  // namespace

PostPerspectiveSpace post_perspective_space(const Camera& camera, float aspect, const ConvexBody& casters, float near,
                                            float extra_shift) {
  const glm::vec3 forward = camera.forward();
  float nearest = INFINITY, farthest = -INFINITY;
  for (const glm::vec3& p : casters.vertices()) {
    const float depth = glm::dot(p - camera.position, forward);
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  if (!(nearest <= farthest)) {  // no casters: the camera's own depth range
    nearest = near;
    farthest = camera.far;
  }
  PostPerspectiveSpace space;
  space.shift = std::max(0.0f, near - nearest) + extra_shift;
  space.near = nearest + space.shift;
  space.far = std::max(farthest + space.shift, space.near * 1.001f);
  Camera virtual_camera = camera;
  virtual_camera.position -= space.shift * forward;
  virtual_camera.target -= space.shift * forward;
  virtual_camera.near = space.near;
  virtual_camera.far = space.far;
  space.matrix = virtual_camera.projection(aspect) * virtual_camera.view();
  return space;
}

glm::vec4 homogeneous(const Light& light) {
  return light.type == LightType::directional ? glm::vec4(-glm::normalize(light.direction), 0.0f)
                                              : glm::vec4(light.position, 1.0f);
}

PostPerspectiveLight post_perspective_light(const glm::mat4& post_perspective, const Light& light) {
  const glm::vec4 q = post_perspective * homogeneous(light);
  if (std::abs(q.w) <= at_infinity * glm::length(glm::vec3(q))) return PostPerspectiveLight::directional;
  return q.w > 0.0f ? PostPerspectiveLight::point : PostPerspectiveLight::inverted;
}

}  // namespace shadow
