#version 450 core
// Depth of the scene as the light sees it.
layout(location = 0) in vec3 position;
#include "instance.glsl"

#ifdef SURFACE_TEXTURES
layout(location = 11) in vec4 surface;  // texture coordinate, material code, keep scale
out vec2 surface_uv;
flat out vec2 surface_material;  // code, keep scale (surface_texture.glsl)
out float surface_keep_scale;     // interpolated
#endif

uniform mat4 light_view_projection;

void main() {
  gl_Position = light_view_projection * (instance_model() * vec4(position, 1.0));
#ifdef SURFACE_TEXTURES
  surface_uv = surface.xy;
  surface_material = surface.zw;
  surface_keep_scale = surface.w;
#endif
}
