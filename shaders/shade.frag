#version 450 core
// The frame's last pass: lights the surface each pixel holds (surface.frag, point_surface.frag).
// Pixels without one keep the sky the targets were cleared to.
layout(binding = 2) uniform sampler2D surface_normals;
layout(binding = 3) uniform sampler2D surface_albedos;
layout(binding = 4) uniform sampler2D surface_depths;  // linear view depth, negative for none

layout(location = 0) out vec4 out_color;       // sRGB
layout(location = 1) out float out_visibility;  // the `shadow` AOV
layout(location = 2) out float out_aliasing;    // the `aliasing` AOV

#include "lighting.glsl"
#include "surface_position.glsl"

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(surface_depths, pixel, 0).r;
  if (depth < 0.0) discard;
  vec3 position = surface_position(gl_FragCoord.xy, depth);
  vec3 n = texelFetch(surface_normals, pixel, 0).xyz;
  Shading s = shade(position, n, texelFetch(surface_albedos, pixel, 0).rgb);
  out_color = vec4(linear_to_srgb(s.color), 1.0);
  out_visibility = s.visibility;
  out_aliasing = aliasing_factor(position, n);
}
