#pragma once
#include <glad/gl.h>

namespace ecoview {

// The texture units of the buffer textures the shaders read plants and point samples from
// (shaders/plant_instances.glsl, shaders/point_samples.glsl).
inline constexpr GLuint instance_texels_unit = 8, position_texels_unit = 9, normal_texels_unit = 10, color_texels_unit = 11;

}  // namespace ecoview
