#pragma once
#include <glm/glm.hpp>

namespace shadow {

// A pinhole camera with OpenGL's projection: vertical field of view, aspect = width / height.
struct Camera {
  glm::vec3 position{0.0f, 8.0f, 12.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_deg = 50.0f;
  float near = 0.1f;
  float far = 200.0f;

  glm::vec3 forward() const { return glm::normalize(target - position); }
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
};

}  // namespace shadow
