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

std::size_t layer_of(const ShadowSetup& setup, const Light& light, const glm::vec3& p) {
  if (setup.selection == ViewSelection::single) return 0;
  if (setup.selection == ViewSelection::first_containing) {
    const float inside = 1.0f - 2.0f * cascade_margin_texels / 2048.0f;  // the tests' map size
    for (std::size_t i = 0; i + 1 < setup.views.size(); ++i) {
      const glm::vec4 clip = setup.views[i].clip(p);
      if (std::abs(clip.x) <= inside * clip.w && std::abs(clip.y) <= inside * clip.w && std::abs(clip.z) <= clip.w) return i;
    }
    return setup.views.size() - 1;
  }
  if (setup.selection == ViewSelection::hemispheres) return (setup.views[0].view * glm::vec4(p, 1.0f)).z <= 0.0f ? 0 : 1;
  const glm::vec3 d = p - light.position, a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0 ? 2 : 3;
  return d.z >= 0 ? 4 : 5;
}

}  // namespace shadow
