#pragma once
#include "app/scene/json_input.hpp"
#include "shadow/camera.hpp"
#include "shadow/light.hpp"

// Readers for the parts of a scene file that camera paths share, each validating what it reads.
namespace ecoview {

shadow::Camera read_camera(const JsonField& field);
shadow::Light read_light(const JsonField& field);
// Fails on `field` when the camera cannot look from position to target with this up vector.
void check_camera_frame(const JsonField& field, const glm::vec3& position, const glm::vec3& target,
                        const glm::vec3& up);
glm::vec3 srgb_to_linear(const glm::vec3& srgb);

}  // namespace ecoview
