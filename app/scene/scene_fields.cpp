#include "app/scene/scene_fields.hpp"

#include "pointgen/srgb.hpp"

#include <cmath>

namespace ecoview {

void check_camera_frame(const JsonField& field, const glm::vec3& position, const glm::vec3& target,
                        const glm::vec3& up) {
  const glm::vec3 forward = target - position;
  if (glm::length(forward) < 1e-6f) field.fail("target equals the camera position");
  if (glm::length(up) < 1e-6f) field.fail("up has zero length");
  if (glm::length(glm::cross(glm::normalize(forward), glm::normalize(up))) < 1e-4f) {
    field.fail("up is parallel to the view direction (target - position)");
  }
}

shadow::Camera read_camera(const JsonField& field) {
  field.only_keys({"position", "target", "up", "fov_y_deg", "near", "far"});
  shadow::Camera camera;
  camera.position = field["position"].vec3();
  camera.target = field["target"].vec3();
  if (auto up = field.optional("up")) camera.up = up->vec3();
  check_camera_frame(field, camera.position, camera.target, camera.up);
  if (auto fov = field.optional("fov_y_deg")) camera.fov_y_deg = fov->number_f(0.01, 179);
  if (auto near = field.optional("near")) camera.near = near->number_f(1e-5, 1e6);
  if (auto far = field.optional("far")) camera.far = far->number_f(1e-5, 1e7);
  if (camera.far <= camera.near * 1.0001f) {
    (field.has("far") ? field["far"] : field).fail("far must be greater than near");
  }
  return camera;
}

shadow::Light read_light(const JsonField& field) {
  shadow::Light light;
  const std::string type = field["type"].string();
  auto direction = [&] {
    const glm::vec3 d = field["direction"].vec3();
    if (glm::length(d) < 1e-6f) field["direction"].fail("has zero length; a light needs a direction");
    return glm::normalize(d);
  };
  if (type == "directional") {
    field.only_keys({"type", "direction"});
    light.type = shadow::LightType::directional;
    light.direction = direction();
  } else if (type == "point") {
    field.only_keys({"type", "position"});
    light.type = shadow::LightType::point;
    light.position = field["position"].vec3();
  } else if (type == "spot") {
    field.only_keys({"type", "position", "direction", "cone_deg"});
    light.type = shadow::LightType::spot;
    light.position = field["position"].vec3();
    light.direction = direction();
    light.cone_deg = field["cone_deg"].number_f(0.1, 89);
  } else {
    field["type"].fail("unknown light type '" + type + "' (known: directional, point, spot)");
  }
  return light;
}

glm::vec3 srgb_to_linear(const glm::vec3& srgb) {
  glm::vec3 out;
  for (int i = 0; i < 3; ++i) {
    out[i] = pointgen::srgb_to_linear(srgb[i]);
  }
  return out;
}

}  // namespace ecoview
