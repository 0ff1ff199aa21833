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

}  // namespace shadow
