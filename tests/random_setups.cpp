#include "random_setups.hpp"

#include <cmath>

namespace shadow {

glm::vec3 random_unit(pointgen::Random& rng) {
  for (;;) {
    const glm::vec3 v(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    if (glm::length(v) > 0.2f && glm::length(v) <= 1.0f) return glm::normalize(v);
  }
}

Box scene_box() {
  Box b;
  b.add(glm::vec3(-50.0f, 0.0f, -50.0f));
  b.add(glm::vec3(50.0f, 20.0f, 50.0f));
  return b;
}

Camera random_camera(pointgen::Random& rng) {
  Camera c;
  c.position = glm::vec3(rng.uniform(-60, 60), rng.uniform(1, 40), rng.uniform(-60, 60));
  c.target = glm::vec3(rng.uniform(-40, 40), rng.uniform(0, 10), rng.uniform(-40, 40));
  if (glm::length(c.target - c.position) < 1.0f) c.target.x += 5.0f;
  c.fov_y_deg = rng.uniform(30, 90);
  c.near = rng.uniform(0.1f, 1.0f);
  c.far = rng.uniform(60, 300);
  return c;
}

Light random_light(pointgen::Random& rng, LightType type) {
  Light l;
  l.type = type;
  l.direction = random_unit(rng);
  l.position = glm::vec3(rng.uniform(-60, 60), rng.uniform(5, 80), rng.uniform(-60, 60));
  l.cone_deg = rng.uniform(20, 70);
  return l;
}

Camera deep_view_camera() {
  Camera camera;
  camera.position = glm::vec3(0, 2, 45);
  camera.target = glm::vec3(0, 1, 0);
  camera.near = 0.5f;
  camera.far = 300.0f;
  return camera;
}

Camera camera_looking(const glm::vec3& position, const glm::vec3& target, float near, float far) {
  Camera c;
  c.position = position;
  c.target = target;
  c.near = near;
  c.far = far;
  return c;
}

glm::vec3 ndc(const glm::mat4& m, const glm::vec3& p) {
  const glm::vec4 c = m * glm::vec4(p, 1.0f);
  return glm::vec3(c) / c.w;
}

float ground_texel_area(const glm::mat4& m, const glm::vec3& p) {
  const float h = 0.5f;
  const glm::vec2 du = (glm::vec2(ndc(m, p + glm::vec3(h, 0, 0))) - glm::vec2(ndc(m, p - glm::vec3(h, 0, 0)))) / (2 * h);
  const glm::vec2 dv = (glm::vec2(ndc(m, p + glm::vec3(0, 0, h))) - glm::vec2(ndc(m, p - glm::vec3(0, 0, h)))) / (2 * h);
  return 1.0f / std::abs(du.x * dv.y - du.y * dv.x);
}

}  // namespace shadow
