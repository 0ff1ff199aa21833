#include "shadow/paraboloid_map.hpp"

#include "shadow/focus_body.hpp"
#include "shadow/light_projection.hpp"
#include "shadow/uniform_map.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace shadow {
namespace {

constexpr float half_pi = 1.5707963f;
// Texels of margin at the rim of a map: the 3x3 bilinear filter reaches two texels out.
constexpr float rim_texels = 4.0f;
// Cones wider than this get the cube of frusta in enclosing_frusta().
constexpr float widest_pyramid_half_angle = glm::radians(80.0f);

// The zoom that fits a cone of `half_angle` around the axis into the map, with rim_texels to
// spare. A texel at angle a from the axis spans 2 zoom (1 + cos a) / map_size radians.
float zoom_for(float half_angle, int map_size) {
  const float rim = rim_texels * 2.0f * std::tan(half_angle / 2.0f) * (1.0f + std::cos(half_angle)) / static_cast<float>(map_size);
  return std::max(std::tan(std::min(half_angle + rim, 0.99f * 3.1415927f) / 2.0f), 1e-4f);
}

// Metres from the light to the farthest receiver, and a little more.
float range_of(const glm::vec3& light, const FocusBodies& bodies) {
  float farthest = 0.0f;
  for (const glm::vec3& p : bodies.receivers.vertices()) farthest = std::max(farthest, glm::distance(light, p));
  return 1.01f * farthest + 1e-3f;
}

ShadowView paraboloid_view(const glm::vec3& light, const glm::vec3& axis, const glm::vec3& forward, float zoom, float range) {
  return {glm::lookAt(light, light + axis, light_up(axis, forward)), Paraboloid{zoom, range}};
}

ShadowSetup dual(const glm::vec3& light, const glm::vec3& axis, const glm::vec3& forward, float range, int map_size,
                 const std::string& description) {
  const float zoom = zoom_for(half_pi, map_size);
  return {{paraboloid_view(light, axis, forward, zoom, range), paraboloid_view(light, -axis, forward, zoom, range)},
          ViewSelection::hemispheres,
          description};
}

}  // namespace

ShadowSetup dual_paraboloid_map(const ShadowInputs& in) {
  const Light& light = in.light;
  if (light.type == LightType::directional) return focused_uniform_map(in);
  return dual(light.position, {0.0f, -1.0f, 0.0f}, in.camera.forward(), range_of(light.position, in.bodies_or_scene), in.map_size,
              "dpsm");
}

ShadowSetup improved_paraboloid_map(const ShadowInputs& in) {
  const Light& light = in.light;
  const int map_size = in.map_size;
  const glm::vec3 forward = in.camera.forward();
  if (light.type == LightType::directional) return focused_uniform_map(in);
  const FocusBodies& bodies = in.bodies_or_scene;
  const Cone cone = cone_around(light.position, bodies.receivers.vertices());
  const float range = range_of(light.position, bodies);
  const float half_angle = std::acos(std::clamp(cone.cos_half_angle, -1.0f, 1.0f));
  if (half_angle > half_pi) return dual(light.position, cone.axis, forward, range, map_size, "ipsm: dual, the light among the receivers");
  return {{paraboloid_view(light.position, cone.axis, forward, zoom_for(half_angle, map_size), range)},
          ViewSelection::single,
          "ipsm"};
}

std::vector<glm::mat4> enclosing_frusta(const ShadowView& view) {
  const Paraboloid& p = *view.paraboloid;
  const float near = 1e-4f * p.range;
  const float half_angle = 2.0f * std::atan(p.zoom);
  if (half_angle <= widest_pyramid_half_angle) {
    return {glm::perspective(2.0f * half_angle, 1.0f, near, p.range) * view.view};
  }
  const glm::vec3 light(glm::inverse(view.view)[3]);
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<glm::mat4> frusta;
  for (const glm::vec3& axis : axes) {
    const glm::vec3 up = std::abs(axis.y) > 0.5f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    frusta.push_back(glm::perspective(half_pi * 1.01f, 1.0f, near, p.range) * glm::lookAt(light, light + axis, up));
  }
  return frusta;
}

}  // namespace shadow
