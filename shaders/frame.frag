#version 450 core
in vec3 world_position;
in vec3 world_normal;
in vec3 albedo;
in float view_depth;

layout(location = 0) out vec4 out_color;       // sRGB
layout(location = 1) out float out_visibility;  // the `shadow` AOV
layout(location = 2) out float out_depth;       // linear view depth, metres
layout(location = 3) out float out_aliasing;    // the `aliasing` AOV

#include "lighting.glsl"

void main() {
  vec3 n = normalize(world_normal);
  if (!gl_FrontFacing) n = -n;
  Shading s = shade(world_position, n, albedo);
  out_color = vec4(linear_to_srgb(s.color), 1.0);
  out_visibility = s.visibility;
  out_depth = view_depth;
  out_aliasing = aliasing_factor(world_position, n);
}
