#pragma once
#include <glm/glm.hpp>

namespace shadow {

enum class LightType { directional, point, spot };

// `direction` is the way the light travels, from the light into the scene (directional, spot).
// `cone_deg` is a spot light's half-angle.
struct Light {
  LightType type = LightType::directional;
  glm::vec3 position{0.0f, 10.0f, 0.0f};
  glm::vec3 direction{0.0f, -1.0f, 0.0f};
  float cone_deg = 30.0f;
};

}  // namespace shadow
