#pragma once
#include "pointgen/instance_table.hpp"

#include <glm/glm.hpp>

namespace ecoview {

// A plant's pose as the shaders read it (shaders/plant_instances.glsl): four RGBA32F texels, the
// three rows of its affine model matrix (the translation in w), then its tint. 64 bytes a plant,
// where the whole matrix and the tint took 80.
struct PlantPose {
  glm::vec4 rows[3];
  glm::vec4 tint;
};

inline PlantPose plant_pose(const pointgen::InstanceTable& table, std::size_t i) {
  const glm::mat4x3& m = table.transforms[i];
  PlantPose pose{};
  for (int r = 0; r < 3; ++r) pose.rows[r] = glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]);
  pose.tint = glm::vec4(table.tint(i), 1.0f);
  return pose;
}

}  // namespace ecoview
