#include "shadow/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace shadow {

glm::mat4 Camera::view() const { return glm::lookAt(position, target, up); }

glm::mat4 Camera::projection(float aspect) const {
  return glm::perspective(glm::radians(fov_y_deg), aspect, near, far);
}

}  // namespace shadow
