#version 450 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 vertex_color;
#include "instance.glsl"
#ifdef SURFACE_TEXTURES
layout(location = 11) in vec4 surface;  // texture coordinate, material code, keep scale
out vec2 surface_uv;
flat out vec2 surface_material;  // code, keep scale (surface_texture.glsl)
out float surface_keep_scale;     // interpolated
#endif

uniform mat4 view;
uniform mat4 view_projection;

out vec3 world_normal;
out vec3 albedo;
out float view_depth;

void main() {
  vec4 world = instance_model() * vec4(position, 1.0);
  world_normal = instance_normal_matrix() * normal;
  albedo = vertex_color * instance_color();
  view_depth = -(view * world).z;
#ifdef SURFACE_TEXTURES
  surface_uv = surface.xy;
  surface_material = surface.zw;
  surface_keep_scale = surface.w;
#endif
  gl_Position = view_projection * world;
}
