#include "shadow/uniform_map.hpp"

#include "shadow/focus_body.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace shadow {
namespace {

// Widest half-angle one perspective map covers for a point light; receivers wider than this
// around the light fall outside the map (an omnidirectional light needs several maps).
constexpr float max_point_half_angle_deg = 75.0f;

glm::vec3 any_perpendicular(const glm::vec3& v) {
  return glm::normalize(std::abs(v.y) < 0.9f ? glm::cross(v, glm::vec3(0, 1, 0))
                                             : glm::cross(v, glm::vec3(1, 0, 0)));
}

// Up vector for a light view along `axis`: the camera's forward direction where it is not
// parallel, so the map's rows follow the view.
glm::vec3 light_up(const glm::vec3& axis, const Camera& camera) {
  const glm::vec3 f = camera.forward();
  const glm::vec3 up = f - glm::dot(f, axis) * axis;
  return glm::length(up) > 1e-3f ? glm::normalize(up) : any_perpendicular(axis);
}

glm::vec3 centroid(const std::vector<glm::vec3>& points) {
  glm::vec3 sum(0.0f);
  for (const glm::vec3& p : points) sum += p;
  return sum / static_cast<float>(points.size());
}

glm::vec3 light_axis(const Light& light, const std::vector<glm::vec3>& receivers) {
  if (light.type != LightType::point) return glm::normalize(light.direction);
  glm::vec3 sum(0.0f);
  for (const glm::vec3& p : receivers) {
    const glm::vec3 d = p - light.position;
    if (glm::length(d) > 0.0f) sum += glm::normalize(d);
  }
  return glm::length(sum) > 1e-6f ? glm::normalize(sum) : glm::vec3(0.0f, -1.0f, 0.0f);
}

ShadowSetup fit_orthographic(const glm::mat4& view, const std::vector<glm::vec3>& receivers,
                             const std::vector<glm::vec3>& casters) {
  Box r, c;
  for (const glm::vec3& p : receivers) r.add(glm::vec3(view * glm::vec4(p, 1.0f)));
  for (const glm::vec3& p : casters) c.add(glm::vec3(view * glm::vec4(p, 1.0f)));
  const glm::vec3 pad = 0.01f * (r.max - r.min) + 1e-4f;
  const float nearest = std::max(r.max.z, c.max.z) + pad.z;  // light space looks down -z
  const float farthest = r.min.z - pad.z;
  return {view, glm::ortho(r.min.x - pad.x, r.max.x + pad.x, r.min.y - pad.y, r.max.y + pad.y,
                           -nearest, -farthest)};
}

ShadowSetup fit_perspective(const glm::mat4& view, float max_tan,
                            const std::vector<glm::vec3>& receivers,
                            const std::vector<glm::vec3>& casters) {
  glm::vec2 lo(max_tan), hi(-max_tan);
  float far = 0.0f;
  for (const glm::vec3& p : receivers) {
    const glm::vec3 q(view * glm::vec4(p, 1.0f));
    const float depth = -q.z;
    far = std::max(far, depth);
    if (depth <= 1e-6f * glm::length(q)) {  // beside or behind the light: widest map
      lo = glm::vec2(-max_tan);
      hi = glm::vec2(max_tan);
      continue;
    }
    const glm::vec2 t = glm::clamp(glm::vec2(q.x, q.y) / depth, -max_tan, max_tan);
    lo = glm::min(lo, t);
    hi = glm::max(hi, t);
  }
  far = std::max(far * 1.01f, 1e-3f);
  float near = far;
  for (const glm::vec3& p : casters) {
    const float depth = -(view * glm::vec4(p, 1.0f)).z;
    if (depth > 0.0f) near = std::min(near, depth);
  }
  near = std::clamp(near * 0.99f, far * 1e-4f, far * 0.5f);
  const glm::vec2 pad = 0.01f * (hi - lo) + 1e-5f;
  lo -= pad;
  hi += pad;
  return {view, glm::frustum(lo.x * near, hi.x * near, lo.y * near, hi.y * near, near, far)};
}

}  // namespace

ShadowSetup focused_uniform_map(const Camera& camera, float aspect, const Light& light,
                                const Box& scene) {
  FocusBodies bodies = focus_bodies(camera.projection(aspect) * camera.view(), light, scene);
  if (bodies.receivers.empty()) {  // the camera sees none of the scene: cover all of it
    bodies.receivers = ConvexBody::from_box(scene);
    bodies.receivers.clip(light_frustum_planes(light));
    bodies.casters = bodies.receivers;
  }
  if (bodies.receivers.empty()) {  // the light does not reach the scene: any valid map will do
    bodies.receivers = bodies.casters = ConvexBody::from_box(scene);
  }
  const std::vector<glm::vec3> receivers = bodies.receivers.vertices();
  std::vector<glm::vec3> casters = bodies.casters.vertices();
  casters.insert(casters.end(), receivers.begin(), receivers.end());

  const glm::vec3 axis = light_axis(light, receivers);
  const glm::vec3 up = light_up(axis, camera);
  if (light.type == LightType::directional) {
    const glm::vec3 center = centroid(receivers);
    return fit_orthographic(glm::lookAt(center - axis, center, up), receivers, casters);
  }
  const float max_tan = light.type == LightType::spot
                            ? std::tan(glm::radians(light.cone_deg))
                            : std::tan(glm::radians(max_point_half_angle_deg));
  return fit_perspective(glm::lookAt(light.position, light.position + axis, up), max_tan,
                         receivers, casters);
}

}  // namespace shadow
