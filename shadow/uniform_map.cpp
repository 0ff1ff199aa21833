#include "shadow/uniform_map.hpp"

#include "shadow/focus_body.hpp"
#include "shadow/light_projection.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace shadow {
namespace {

ShadowView fit_orthographic(const glm::mat4& view, const FocusBodies& bodies) {
  Box r, c;
  for (const glm::vec3& p : bodies.receivers.vertices()) r.add(glm::vec3(view * glm::vec4(p, 1.0f)));
  for (const glm::vec3& p : bodies.casters.vertices()) c.add(glm::vec3(view * glm::vec4(p, 1.0f)));
  const glm::vec3 pad = 0.01f * (r.max - r.min) + 1e-4f;
  const float nearest = std::max(r.max.z, c.max.z) + pad.z;  // light space looks down -z
  const float farthest = r.min.z - pad.z;
  return {view, glm::ortho(r.min.x - pad.x, r.max.x + pad.x, r.min.y - pad.y, r.max.y + pad.y,
                           -nearest, -farthest)};
}

// The perspective projection of a light view whose pyramid has the side tangents lo..hi: far
// reaches the last receiver inside the pyramid, near the first caster inside it (kept off zero
// for depth precision).
glm::mat4 pyramid_projection(const glm::mat4& view, glm::vec2 lo, glm::vec2 hi, const FocusBodies& bodies) {
  const Plane sides[4] = {Plane::through(glm::vec3(0.0f), {1, 0, hi.x}), Plane::through(glm::vec3(0.0f), {-1, 0, -lo.x}),
                          Plane::through(glm::vec3(0.0f), {0, 1, hi.y}), Plane::through(glm::vec3(0.0f), {0, -1, -lo.y})};
  ConvexBody receivers = bodies.receivers.transformed(view);
  ConvexBody casters = bodies.casters.transformed(view);
  receivers.clip(sides);
  casters.clip(sides);
  float far = 0.0f;
  for (const glm::vec3& p : receivers.vertices()) far = std::max(far, -p.z);
  far = std::max(far * 1.01f, 1e-3f);
  float near = far;
  for (const glm::vec3& p : casters.vertices()) near = std::min(near, -p.z);
  near = std::clamp(near * 0.99f, far * 1e-4f, far * 0.5f);
  return glm::frustum(lo.x * near, hi.x * near, lo.y * near, hi.y * near, near, far);
}

// One perspective view fitted around the receivers, within max_tan of its axis.
ShadowView fit_perspective(const glm::mat4& view, float max_tan, const FocusBodies& bodies) {
  glm::vec2 lo(max_tan), hi(-max_tan);
  for (const glm::vec3& p : bodies.receivers.vertices()) {
    const glm::vec3 q(view * glm::vec4(p, 1.0f));
    if (-q.z <= 1e-6f * glm::length(q)) {  // beside or behind the light: widest map
      lo = glm::vec2(-max_tan);
      hi = glm::vec2(max_tan);
      continue;
    }
    const glm::vec2 t = glm::clamp(glm::vec2(q.x, q.y) / -q.z, -max_tan, max_tan);
    lo = glm::min(lo, t);
    hi = glm::max(hi, t);
  }
  const glm::vec2 pad = 0.01f * (hi - lo) + 1e-5f;
  return {view, pyramid_projection(view, lo - pad, hi + pad, bodies)};
}

// The six 90° views of a cube around a point light, each a little wider than 90° so that
// filtering near a face's edge stays inside that face's map.
ShadowSetup cube_faces(const glm::vec3& light, const FocusBodies& bodies, int map_size) {
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  const glm::vec2 tan_half(1.0f + 8.0f / static_cast<float>(map_size));
  ShadowSetup setup{{}, ViewSelection::cube_faces, "uniform: cube faces"};
  for (int face = 0; face < 6; ++face) {
    const glm::mat4 view = glm::lookAt(light, light + axes[face], ups[face]);
    setup.views.push_back({view, pyramid_projection(view, -tan_half, tan_half, bodies)});
  }
  return setup;
}

// Orthographic for a directional light, perspective otherwise, fitted to `bodies`; `forward`
// orients the map's rows.
ShadowSetup uniform_map(const FocusBodies& bodies, const Light& light, const glm::vec3& forward, int map_size) {
  switch (light.type) {
    case LightType::directional: {
      const glm::vec3 axis = glm::normalize(light.direction);
      const glm::vec3 center = bodies.receivers.centroid();
      return {{fit_orthographic(glm::lookAt(center - axis, center, light_up(axis, forward)), bodies)}};
    }
    case LightType::spot: {
      const glm::vec3 axis = glm::normalize(light.direction);
      const glm::mat4 view = glm::lookAt(light.position, light.position + axis, light_up(axis, forward));
      return {{fit_perspective(view, std::tan(glm::radians(light.cone_deg)), bodies)}};
    }
    case LightType::point: {
      const Cone cone = cone_around(light.position, bodies.receivers.vertices());
      if (cone.cos_half_angle < std::cos(glm::radians(max_single_map_half_angle_deg))) {
        return cube_faces(light.position, bodies, map_size);
      }
      const glm::mat4 view = glm::lookAt(light.position, light.position + cone.axis, light_up(cone.axis, forward));
      return {{fit_perspective(view, std::tan(glm::radians(max_single_map_half_angle_deg)), bodies)}};
    }
  }
  return {};
}

}  // namespace

ShadowSetup focused_uniform_map(const ShadowInputs& in) {
  return uniform_map(in.bodies_or_scene, in.light, in.camera.forward(), in.map_size);
}

ShadowSetup lit_scene_map(const ShadowInputs& in) {
  const glm::vec3 world_forward(0.0f, 0.0f, -1.0f);
  return uniform_map(or_scene({}, in.light, in.scene), in.light, world_forward, in.map_size);
}

}  // namespace shadow
