#version 450 core
layout(triangles, equal_spacing, ccw) in;

in vec3 patch_position[];
#ifdef SURFACE_TEXTURES
in vec4 patch_surface[];
out vec2 surface_uv;
flat out vec2 surface_material;  // code, keep scale (surface_texture.glsl)
out float surface_keep_scale;     // interpolated
#endif

uniform mat4 light_view;
uniform vec2 paraboloid;  // zoom, range

#include "paraboloid.glsl"

void main() {
  vec3 p = gl_TessCoord.x * patch_position[0] + gl_TessCoord.y * patch_position[1] + gl_TessCoord.z * patch_position[2];
  gl_Position = paraboloid_clip(light_view, paraboloid, p);
  // Cut away what lies more than 120 degrees off the axis, beyond the map's disc: a piece around
  // the pole behind the light would have all its corners far out in different directions, and
  // cover the whole map.
  vec3 q = (light_view * vec4(p, 1.0)).xyz;
  gl_ClipDistance[0] = 0.5 - q.z / max(length(q), 1e-20);
#ifdef SURFACE_TEXTURES
  surface_uv = gl_TessCoord.x * patch_surface[0].xy + gl_TessCoord.y * patch_surface[1].xy + gl_TessCoord.z * patch_surface[2].xy;
  surface_material = patch_surface[0].zw;
  surface_keep_scale = dot(gl_TessCoord, vec3(patch_surface[0].w, patch_surface[1].w, patch_surface[2].w));
#endif
}
