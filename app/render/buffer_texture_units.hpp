#pragma once
#include <glad/gl.h>

namespace ecoview {

// The texture units of the buffer textures the shaders read plants, point samples, the sampled
// meshes and depth pyramids from (shaders/plant_instances.glsl, shaders/point_samples.glsl,
// shaders/sample_common.glsl, shaders/depth_pyramid.glsl).
inline constexpr GLuint instance_texels_unit = 8, position_texels_unit = 9, normal_texels_unit = 10, color_texels_unit = 11,
                        mesh_texels_unit = 12, plant_mesh_texels_unit = 13, pyramid_texels_unit = 14;
// The meshes' base-colour textures, a texture array (shaders/surface_texture.glsl).
inline constexpr GLuint surface_texture_unit = 15;
// A shadow silhouette map's points and their edges' depths, for the frame's lighting (shaders/lighting.glsl).
inline constexpr GLuint silhouette_points_unit = 16, silhouette_depths_unit = 18;
// A virtual paged map's page table (shaders/virtual_pages.glsl).
inline constexpr GLuint page_table_unit = 17;

}  // namespace ecoview
